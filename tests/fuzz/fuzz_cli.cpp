// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: pgloss-tracer's argument parser (examples/tracer/src/cli.cpp). The input
// is split at NUL bytes into arguments. Every argument list either parses into options inside
// pgt::limits or throws CliError; anything else is a finding.
#include "fuzz_common.hpp"

#include "cli.hpp"
#include "scene.hpp"

#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size) {
    std::vector<std::string> args(1);
    for (size_t k = 0; k < size; ++k) {
        if (data[k] == 0) args.emplace_back();
        else args.back() += char(data[k]);
    }
    pgt::CliOptions o;
    try {
        o = pgt::parse_cli(args);
    } catch (const pgt::CliError &) {
        return 0;
    }
    FZ_CHECK(o.width == 0 || (o.width >= 1 && o.width <= pgt::limits::image_side));
    FZ_CHECK(o.height == 0 || (o.height >= 1 && o.height <= pgt::limits::image_side));
    FZ_CHECK(o.spp == 0 || (o.spp >= 1 && o.spp <= pgt::limits::spp));
    FZ_CHECK(o.threads == 0 || (o.threads >= 1 && o.threads <= pgt::limits::threads));
    FZ_CHECK(o.seed >= -1 && o.seed <= long(pgt::limits::seed));
    FZ_CHECK(o.time_s == 0 || (o.time_s > 0 && o.time_s <= 1e7));
    FZ_CHECK(o.mode.empty() || o.mode == "mis" || o.mode == "brdf" || o.mode == "light");
    if (o.command == pgt::CliOptions::Command::RENDER) FZ_CHECK(!o.out.empty());
    return 0;
}
