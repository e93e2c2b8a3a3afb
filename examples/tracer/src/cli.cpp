// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// cli.cpp — see cli.hpp.
#include "cli.hpp"

#include "scene.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace pgt {

CliError::CliError(const std::string &what) : std::runtime_error(printable(what)) {}

namespace {

// Whole-string numbers: "3x", "abc", "" and out-of-range values are errors that name the option.
long long parse_integer(const std::string &opt, const std::string &v, long long lo, long long hi) {
    char *end = nullptr;
    errno = 0;
    long long x = v.empty() ? 0 : std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE || std::isspace(static_cast<unsigned char>(v[0])))
        throw CliError(opt + " wants a whole number, not '" + v + "'");
    if (x < lo || x > hi)
        throw CliError(opt + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + v);
    return x;
}

double parse_seconds(const std::string &opt, const std::string &v) {
    char *end = nullptr;
    double x = v.empty() ? 0 : std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x) || std::isspace(static_cast<unsigned char>(v[0])))
        throw CliError(opt + " wants seconds, not '" + v + "'");
    if (!(x > 0 && x <= 1e7)) throw CliError(opt + " must be in (0, 1e7] seconds, not " + v);
    return x;
}

}  // namespace

std::string output_prefix(const std::string &out) {
    std::string ext = std::filesystem::path(out).extension().string();
    for (char &c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".exr" || ext == ".png") return out.substr(0, out.size() - ext.size());
    for (const char *e : {".jpg", ".jpeg", ".tif", ".tiff", ".hdr", ".bmp", ".tga", ".webp", ".ppm"})
        if (ext == e)
            throw CliError("--out is a prefix (OUT.exr and OUT.png are written), so '" + out + "' would make '" +
                           out + ".exr'; give it without '" + ext + "'");
    return out;
}

CliOptions parse_cli(const std::vector<std::string> &args) {
    CliOptions o;
    if (args.empty()) throw CliError("no command (render, fig4, fig12; --help)");
    const std::string &cmd = args[0];
    size_t i = 1;
    if (cmd == "--version") {
        o.command = CliOptions::Command::VERSION;
        return o;
    } else if (cmd == "-h" || cmd == "--help") {
        return o;
    } else if (cmd == "render") {
        if (args.size() < 2) throw CliError("render needs a scene file: pgloss-tracer render SCENE [options]");
        o.command = CliOptions::Command::RENDER;
        o.scene_path = args[1];
        i = 2;
    } else if (cmd == "fig4" || cmd == "fig12") {
        o.command = cmd == "fig4" ? CliOptions::Command::FIG4 : CliOptions::Command::FIG12;
    } else {
        throw CliError("unknown command '" + cmd + "' (render, fig4, fig12; --help)");
    }
    for (; i < args.size(); ++i) {
        const std::string &a = args[i];
        auto val = [&]() -> const std::string & {
            if (i + 1 >= args.size()) throw CliError("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "--out") o.out = val();
        else if (a == "--scene") o.scene_path = val();
        else if (a == "--size") {
            const std::string &v = val();
            size_t x = v.find('x');
            if (x == std::string::npos) throw CliError("--size wants WxH, e.g. 160x120, not '" + v + "'");
            o.width = int(parse_integer("--size width", v.substr(0, x), 1, limits::image_side));
            o.height = int(parse_integer("--size height", v.substr(x + 1), 1, limits::image_side));
            if (static_cast<long long>(o.width) * o.height > limits::pixels)
                throw CliError("--size: at most " + std::to_string(limits::pixels) + " pixels");
        } else if (a == "--spp") o.spp = int(parse_integer(a, val(), 1, limits::spp));
        else if (a == "--time") o.time_s = parse_seconds(a, val());
        else if (a == "--mode") {
            o.mode = val();
            if (o.mode != "mis" && o.mode != "brdf" && o.mode != "light")
                throw CliError("--mode must be mis, brdf or light, not '" + o.mode + "'");
        } else if (a == "--sampler") {
            o.sampler = val();
            if (o.sampler != "independent" && o.sampler != "sobol")
                throw CliError("--sampler must be independent or sobol, not '" + o.sampler + "'");
        } else if (a == "--light-sampling") {
            o.light_sampling = val();
            if (o.light_sampling != "solid-angle" && o.light_sampling != "area")
                throw CliError("--light-sampling must be solid-angle or area, not '" + o.light_sampling + "'");
        } else if (a == "--seed") o.seed = long(parse_integer(a, val(), 0, long(limits::seed)));
        else if (a == "--threads") o.threads = int(parse_integer(a, val(), 1, limits::threads));
        else if (a == "--quiet") o.quiet = true;
        else if (a == "--embree") o.embree = true;
        else if (a == "-h" || a == "--help") {
            o.command = CliOptions::Command::HELP;
            return o;
        } else throw CliError("unknown option '" + a + "'");
    }
    if (o.command == CliOptions::Command::RENDER) o.out = output_prefix(o.out.empty() ? "out/" + std::filesystem::path(o.scene_path).stem().string() : o.out);
    return o;
}

}  // namespace pgt
