// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// cli.hpp — pgloss-tracer's command line, parsed into options (no I/O, so that it can be
// tested and fuzzed on its own). Every value is checked whole and against pgt::limits.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace pgt {

// The message is printable() (scene.hpp): arguments are echoed in it.
struct CliError : std::runtime_error {
    explicit CliError(const std::string &what);
};

struct CliOptions {
    enum class Command { RENDER, FIG4, FIG12, HELP, VERSION } command = Command::HELP;
    std::string scene_path;  // render: required; figures: "" means the shipped stimulus scene
    std::string out;         // render: a prefix (a trailing .exr/.png is taken off); figures: a folder
    int width = 0, height = 0, spp = 0, threads = 0;  // 0: not given
    long seed = -1;                                   // -1: not given
    double time_s = 0;                                // 0: not given
    std::string mode;                                 // "": not given; else mis, brdf or light
    std::string sampler;                              // "": not given; else independent or sobol
    std::string light_sampling;                       // "": not given; else solid-angle or area
    bool embree = false;                              // --embree: every ray through Embree
    bool quiet = false;
};

// args excludes the program name. Throws CliError with a message that names the option.
CliOptions parse_cli(const std::vector<std::string> &args);

// --out for `render`: a trailing .exr or .png is taken off; another image extension is an
// error rather than a file called OUT.jpg.exr.
std::string output_prefix(const std::string &out);

}  // namespace pgt
