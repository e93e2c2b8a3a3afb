// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// libFuzzer harness: the pgloss tool (tools/), in-process. The input is split at NUL bytes into
// the arguments after the program name. Every argument list either is wrong (exit 2: nothing on
// stdout, a "pgloss" message on stderr) or gets a result (exit 0 or 1: a status line last on
// stdout, or for `bridge` the JSON's "status"; no NaN or Inf printed); a number the grammar takes
// is finite and is strtod's value. Not run: `glossmeter --bench` (seconds of timing) and
// `bridge --from` (it opens the file named, and a name such as /dev/stdin would wait for input).
#include "fuzz_common.hpp"

#include "cli_common.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

std::string text_of(char *buf, size_t n) {
    std::string s(buf ? buf : "", buf ? n : 0);
    std::free(buf);
    return s;
}

// A printed NaN or Inf ("nan", "-inf", ...): the letters as a word, not inside one ("paintinfo.com").
bool prints_nonfinite(const std::string &o) {
    const auto letter = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z'); };
    for (const char *w : {"nan", "inf"})
        for (size_t at = o.find(w); at != std::string::npos; at = o.find(w, at + 1))
            if ((at == 0 || !letter(o[at - 1])) && (at + 3 == o.size() || !letter(o[at + 3]))) return true;
    return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, size_t size) {
    std::vector<std::string> args(2);
    args[0] = "pgloss";
    for (size_t k = 0; k < size && args.size() < 16; ++k) {
        if (data[k] == 0) args.emplace_back();
        else args.back() += char(data[k]);
    }
    if (args.size() > 2 && ((args[1] == "glossmeter" && args[2] == "--bench") ||
                            (args[1] == "bridge" && args[2] == "--from")))
        return 0;
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    char *obuf = nullptr, *ebuf = nullptr;
    size_t on = 0, en = 0;
    FILE *out = open_memstream(&obuf, &on), *err = open_memstream(&ebuf, &en);
    FZ_CHECK(out && err);
    const int rc = pgloss_cli_main(int(args.size()), argv.data(), out, err);
    std::fclose(out);
    std::fclose(err);
    const std::string o = text_of(obuf, on), e = text_of(ebuf, en);

    const bool help = args[1] == "--help" || args[1] == "-h" || args[1] == "--version" ||
                      (args.size() == 3 && (args[2] == "--help" || args[2] == "-h"));
    FZ_CHECK(rc == 0 || rc == 1 || rc == 2);
    if (rc == 2) {
        FZ_CHECK(o.empty());
        FZ_CHECK(e.rfind("pgloss", 0) == 0 && e.back() == '\n');
    } else if (args[1] == "bridge" && !help) {
        FZ_CHECK(e.empty() && o.front() == '{' && o.substr(o.size() - 2) == "}\n");
        const size_t at = o.find("\"status\": \"");
        FZ_CHECK(at != std::string::npos);
        FZ_CHECK((rc == 1) == (o.compare(at + 11, 11, "PGLOSS_ERR_") == 0));
        FZ_CHECK(!prints_nonfinite(o));
    } else if (!help && args[1] != "demo" && !(args[1] == "glossmeter" && args.size() > 2 && args[2] == "--fig4") &&
               !(args[1] == "finish" && (args.size() == 2 || args[2] == "--list"))) {
        FZ_CHECK(e.empty());
        const size_t last = o.rfind("status: ");
        FZ_CHECK(last != std::string::npos && o.find('\n', last) == o.size() - 1);
        const std::string error = "status: PGLOSS_ERR_";
        FZ_CHECK((rc == 1) == (o.compare(last, error.size(), error) == 0));
        FZ_CHECK(!prints_nonfinite(o.substr(0, last)));
    }

    // The grammar on its own: accepted means finite and equal to strtod's reading.
    static const pgloss_cli_command probe = {"probe", "x", "", nullptr};
    FILE *null = std::fopen("/dev/null", "w");
    pgloss_cli cli = {null, null, &probe};
    for (size_t k = 1; k < args.size(); ++k) {
        double v = 0.0;
        if (pgloss_cli_number(&cli, "x", args[k].c_str(), &v)) {
            FZ_CHECK(std::isfinite(v));
            FZ_CHECK(v == std::strtod(args[k].c_str(), nullptr));
            for (char ch : args[k]) FZ_CHECK((ch >= '0' && ch <= '9') || ch == '.' || ch == 'e' || ch == 'E' ||
                                             ch == '+' || ch == '-');
        }
    }
    std::fclose(null);
    return 0;
}
