#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# pgloss as a C/C++ package: installs the static and the shared library into
# fresh prefixes (build-package/prefix-*), then builds and runs a C and a C++ consumer
# (tests/package/) through find_package(pgloss MAJOR.MINOR CONFIG REQUIRED), pkg-config,
# add_subdirectory and FetchContent (from a tarball of this tree: no network); checks that a
# parent project keeps its build type and flags and installs nothing of pgloss; checks that
# the shared library exports exactly the functions the public headers declare (the compiler's
# list of them, gcc -aux-info, against nm -D), its soname, and that the installed tool runs.
# Quick when run again: the build folders are kept, the prefixes are made afresh.
set -euo pipefail
cd "$(dirname "$0")/.."
export PGLOSS_REQUIRE_ALL="${PGLOSS_REQUIRE_ALL:-1}"
bash scripts/bootstrap.sh apt g++ pkg-config binutils tar gzip python3

root=$PWD
work=$root/build-package
mkdir -p "$work/logs"

# The one place the version is written (libpgloss/include/pgloss/version.h).
vh=libpgloss/include/pgloss/version.h
version=$(sed -n 's/^#define PGLOSS_VERSION_STRING "\(.*\)"$/\1/p' "$vh")
major=$(sed -n 's/^#define PGLOSS_VERSION_MAJOR \([0-9]*\)$/\1/p' "$vh")
minor=$(sed -n 's/^#define PGLOSS_VERSION_MINOR \([0-9]*\)$/\1/p' "$vh")
patch=$(sed -n 's/^#define PGLOSS_VERSION_PATCH \([0-9]*\)$/\1/p' "$vh")
# The ABI promise (CHANGELOG.md): libpgloss.so.0.MINOR while the major version is 0, then .MAJOR.
if ((major == 0)); then soversion=$major.$minor; else soversion=$major; fi
echo "== pgloss $version (soname libpgloss.so.$soversion)"

passed=0 failed=0 failures=()
# check NAME COMMAND...: runs the command with its output in build-package/logs/NAME.log.
check() {
  local name=$1; shift
  local log=$work/logs/$name.log rc
  # Not `if (…)`: bash ignores set -e inside a condition; here every command must succeed.
  set +e
  (set -e; "$@") >"$log" 2>&1
  rc=$?
  set -e
  if ((rc == 0)); then
    passed=$((passed + 1)); echo "PASS $name"
  else
    failed=$((failed + 1)); failures+=("$name"); echo "FAIL $name (log: ${log#"$root"/})"
    tail -n 25 "$log" | sed 's/^/     /'
  fi
}

version_in_one_place() {
  [[ $version == "$major.$minor.$patch" ]] || { echo "version.h: STRING $version != $major.$minor.$patch"; return 1; }
  # The shader headers cannot include version.h: their copies must agree with it.
  local f part v
  for f in glsl/pgloss.glsl osl/pgloss.h; do
    for part in MAJOR MINOR PATCH; do
      v=${part,,}
      grep -qx "#define PGLOSS_VERSION_$part ${!v}" "$f" ||
        { echo "$f: PGLOSS_VERSION_$part is not ${!v}"; return 1; }
    done
  done
  grep -qx "#define PGLOSS_VERSION_STRING \"$version\"" osl/pgloss.h || { echo "osl/pgloss.h: STRING"; return 1; }
  grep -q "input = \"$vh\"" pyproject.toml || { echo "pyproject.toml does not read $vh"; return 1; }
  echo "version $version: version.h, glsl/pgloss.glsl, osl/pgloss.h agree; pyproject reads version.h"
}

# build_install TYPE PRESET: configure with the preset in build-package-TYPE/, install afresh.
build_install() {
  # The build folder beside the tree's others (build-package-TYPE/, as deep as build-test/), so
  # that the compiler cache serves the static build from the core layer's (scripts/ccache.sh).
  local type=$1 preset=$2 prefix=$work/prefix-$1 build=$root/build-package-$1
  cmake --preset "$preset" -B "$build" -DCMAKE_INSTALL_PREFIX=/nonexistent
  cmake --build "$build"
  rm -rf "$prefix"
  # --prefix at install time (not the configured one): the packages must not depend on it.
  cmake --install "$build" --prefix "$prefix"
  grep -q "CMAKE_PROJECT_VERSION:STATIC=$version\$" "$build/CMakeCache.txt"
  (cd "$prefix" && find . -type f -o -type l | sed 's|^\./||' | sort) | tee "$work/installed-$type.txt"
}

installed_files() { # TYPE: the files every install must hold
  local type=$1 prefix=$work/prefix-$1 f
  local want=(include/pgloss/pgloss.h include/pgloss/version.h include/pgloss/export.h
    lib/cmake/pgloss/pglossConfig.cmake lib/cmake/pgloss/pglossConfigVersion.cmake
    lib/cmake/pgloss/pglossTargets.cmake lib/pkgconfig/pgloss.pc bin/pgloss
    share/doc/pgloss/LICENSE share/doc/pgloss/CITATION.cff share/doc/pgloss/CHANGELOG.md)
  if [[ $type == shared ]]; then
    want+=(lib/libpgloss.so "lib/libpgloss.so.$soversion" "lib/libpgloss.so.$version")
  else
    want+=(lib/libpgloss.a)
  fi
  for f in "${want[@]}"; do [[ -e $prefix/$f ]] || { echo "missing $f"; return 1; }; done
  # Every public header of the source tree is installed.
  for f in libpgloss/include/pgloss/*.h; do [[ -f $prefix/include/${f#libpgloss/include/} ]] || { echo "missing ${f#libpgloss/}"; return 1; }; done
  if [[ $type == static ]] && compgen -G "$prefix/lib/libpgloss.so*"; then echo "a shared library in the static install"; return 1; fi
  echo "all ${#want[@]} expected files present"
}

run_consumers() { # BUILD_DIR: run both consumers
  "$1/consumer_c" && "$1/consumer_cxx"
}

find_package_consumer() { # TYPE
  local type=$1 dir=$work/consumer-find-$1
  rm -rf "$dir"
  cmake -S tests/package -B "$dir" -G Ninja -DPGLOSS_MODE=find_package -DPGLOSS_REQUEST="$major.$minor" \
    -DCMAKE_PREFIX_PATH="$work/prefix-$type" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$dir"
  run_consumers "$dir"
  if [[ $type == shared ]]; then
    ldd "$dir/consumer_c" | grep -F "libpgloss.so.$soversion => $work/prefix-$type/lib/"
  elif ldd "$dir/consumer_c" | grep libpgloss; then
    echo "the static consumer loads a shared libpgloss"; return 1
  fi
}

# find_package(pgloss REQUEST) in a minimal project: is the installed version found?
find_version() { # REQUEST EXPECT(found|not-found)
  local probe=$work/version-probe out
  mkdir -p "$probe"
  cat >"$probe/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.18)
project(version_probe LANGUAGES C)
find_package(pgloss ${req} CONFIG QUIET PATHS ${prefix} NO_DEFAULT_PATH)
message(STATUS "found=${pgloss_FOUND} version=${pgloss_VERSION}")
CM
  rm -rf "$probe/build"
  out=$(cmake -S "$probe" -B "$probe/build" -Dreq="$1" -Dprefix="$work/prefix-static" 2>&1 | grep "found=")
  echo "find_package(pgloss $1): $out (want $2)"
  if [[ $2 == found ]]; then [[ $out == *"found=1 version=$version"* ]]; else [[ $out == *"found=0"* ]]; fi
}

version_compatibility() {
  find_version "$major.$minor" found
  find_version "$version" found
  find_version "$((major + 1)).0" not-found
  find_version "$major.$((minor + 1))" not-found
  if ((major == 0)); then
    # 0.y: a minor release may break the API, so an older 0.y request is not satisfied.
    ((minor == 0)) || find_version "0.$((minor - 1))" not-found
  else
    ((minor == 0)) || find_version "$major.$((minor - 1))" found
  fi
}

pkg_config_consumer() { # TYPE
  local type=$1 prefix=$work/prefix-$1 dir=$work/consumer-pc-$1
  export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
  [[ $(pkg-config --modversion pgloss) == "$version" ]]
  pkg-config --atleast-version="$major.$minor" pgloss
  local rpath=() cflags libs
  [[ $type == shared ]] && rpath=(-Wl,-rpath,"$prefix/lib")
  cflags=$(pkg-config --cflags pgloss) libs=$(pkg-config --libs pgloss)
  echo "cflags: $cflags | libs: $libs"
  rm -rf "$dir" && mkdir -p "$dir"
  # shellcheck disable=SC2086
  cc -std=c11 -Wall -Wextra -Wpedantic -Werror tests/package/consumer.c $cflags -o "$dir/consumer_c" $libs "${rpath[@]}" -lm
  # shellcheck disable=SC2086
  c++ -std=c++17 -Wall -Wextra -Wpedantic -Werror tests/package/consumer.cpp $cflags -o "$dir/consumer_cxx" $libs "${rpath[@]}"
  run_consumers "$dir"
}

relocated_prefix() { # the static install, moved: pkg-config and find_package follow it
  local moved=$work/prefix-moved dir=$work/consumer-moved
  rm -rf "$moved" "$dir" && cp -a "$work/prefix-static" "$moved"
  [[ $(PKG_CONFIG_PATH=$moved/lib/pkgconfig pkg-config --variable=includedir pgloss) -ef $moved/include ]]
  cmake -S tests/package -B "$dir" -G Ninja -DPGLOSS_MODE=find_package -DPGLOSS_REQUEST="$major.$minor" \
    -DCMAKE_PREFIX_PATH="$moved" -DCMAKE_BUILD_TYPE=Release
  grep -F "pgloss_DIR:PATH=$moved/lib/cmake/pgloss" "$dir/CMakeCache.txt"
  cmake --build "$dir" && run_consumers "$dir"
}

exports() {
  local lib=$work/prefix-shared/lib/libpgloss.so.$version
  # The functions the public headers declare, listed by the compiler (gcc -aux-info), static
  # inline definitions excluded: an independent list of what must be exported.
  local tu=$work/logs/all-headers.c
  for f in "$work"/prefix-shared/include/pgloss/*.h; do echo "#include <pgloss/${f##*/}>"; done >"$tu"
  gcc -std=c11 -c "$tu" -o /dev/null -I"$work/prefix-shared/include" -aux-info "$work/logs/aux-info.txt"
  grep -F "/include/pgloss/" "$work/logs/aux-info.txt" | grep -F '*/ extern ' |
    sed -E 's/.* \**(pgloss_[A-Za-z0-9_]+) \(.*/\1/' | sort -u >"$work/declared.txt"
  nm -D --defined-only "$lib" | awk '{print $3}' | sort -u >"$work/exported.txt"
  echo "declared in the public headers: $(wc -l <"$work/declared.txt"), exported by libpgloss.so: $(wc -l <"$work/exported.txt")"
  echo "internal pgloss__ symbols exported: $(grep -c '^pgloss__' "$work/exported.txt" || true)"
  [[ -s $work/declared.txt ]]
  diff -u "$work/declared.txt" "$work/exported.txt"
}

soname() {
  local so
  so=$(readelf -d "$work/prefix-shared/lib/libpgloss.so.$version" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
  echo "soname: $so"
  [[ $so == "libpgloss.so.$soversion" ]]
  [[ $(readlink "$work/prefix-shared/lib/libpgloss.so.$soversion") == "libpgloss.so.$version" ]]
  [[ $(readlink "$work/prefix-shared/lib/libpgloss.so") == "libpgloss.so.$soversion" ]]
}

installed_cli() { # TYPE
  local prefix=$work/prefix-$1 out
  out=$(env -u LD_LIBRARY_PATH "$prefix/bin/pgloss" --version)
  echo "bin/pgloss --version: $out"
  [[ $out == "pgloss $version" ]]
  "$prefix/bin/pgloss" check 0.767 0.099 0.04
  if [[ $1 == shared ]]; then
    readelf -d "$prefix/bin/pgloss" | grep -E 'R(UN)?PATH.*\[\$ORIGIN/\.\./lib\]'
    ldd "$prefix/bin/pgloss" | grep -F "libpgloss.so.$soversion => $prefix/bin/../lib/"
  fi
}

# pgloss's own sources compiled without -Werror, and with the parent's CMAKE_C_FLAGS.
no_werror() { # PARENT_BUILD
  python3 - "$1/compile_commands.json" <<'PY'
import json, sys
cmds = [e for e in json.load(open(sys.argv[1])) if "/libpgloss/src/" in e["file"]]
assert cmds, "no pgloss sources in compile_commands.json"
bad = [e["file"] for e in cmds if "-Werror" in e["command"]]
assert not bad, f"pgloss compiled with -Werror as a subproject: {bad}"
assert all("-DCONSUMER_C_FLAGS=1" in e["command"] for e in cmds), "the parent's CMAKE_C_FLAGS were dropped"
print(f"{len(cmds)} pgloss sources compiled without -Werror, with the parent's CMAKE_C_FLAGS")
PY
}

installs_nothing() { # PARENT_BUILD: the parent's install holds its own programs only
  local dest=$1-install
  rm -rf "$dest"
  cmake --install "$1" --prefix "$dest"
  local got
  got=$(cd "$dest" && find . -type f -o -type l | sed 's|^\./||' | sort | tr '\n' ' ')
  echo "the parent installed: $got"
  [[ $got == "bin/consumer_c bin/consumer_cxx " ]]
}

subdirectory_consumer() { # the parent has no build type; pgloss builds static
  local dir=$work/consumer-subdirectory
  cmake -S tests/package -B "$dir" -G Ninja -DPGLOSS_MODE=subdirectory -DPGLOSS_SOURCE_DIR="$root"
  grep -x "CMAKE_BUILD_TYPE:STRING=" "$dir/CMakeCache.txt"
  grep -x "PGLOSS_INSTALL:BOOL=OFF" "$dir/CMakeCache.txt"
  grep -x "PGLOSS_WERROR:BOOL=OFF" "$dir/CMakeCache.txt"
  cmake --build "$dir"
  [[ ! -e $dir/pgloss/tools ]]
  no_werror "$dir"
  run_consumers "$dir"
  installs_nothing "$dir"
}

fetchcontent_consumer() { # a Debug parent with BUILD_SHARED_LIBS=ON
  local dir=$work/consumer-fetchcontent tarball=$work/pgloss-src.tar.gz
  # The tree as a fresh clone has it (tracked and new files, nothing ignored), reproducibly,
  # so that the hash (and the fetched copy) change only when the sources do.
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files -z --cached --others --exclude-standard
  else # a tree without git: leave out what .gitignore ignores
    find . \( -path './build*' -o -path ./out -o -path './.venv*' -o -path ./.git -o -path ./.gl \
      -o -path ./.whl -o -name __pycache__ -o -name .pytest_cache \) -prune -o \
      \( -type f -o -type l \) ! -name '*.pyc' ! -name '*.oso' -printf '%P\0'
  fi | LC_ALL=C sort -z | tar --null -T - --transform 's|^|pgloss/|' --mtime=@0 --owner=0 --group=0 --numeric-owner \
        --mode=u+rw,go+r -cf - | gzip -n >"$tarball.new"
  cmp -s "$tarball.new" "$tarball" 2>/dev/null && rm "$tarball.new" || mv "$tarball.new" "$tarball"
  local sha
  sha=$(sha256sum "$tarball" | cut -d' ' -f1)
  cmake -S tests/package -B "$dir" -G Ninja -DPGLOSS_MODE=fetchcontent -DPGLOSS_URL="$tarball" \
    -DPGLOSS_URL_SHA256="$sha" -DCMAKE_BUILD_TYPE=Debug -DBUILD_SHARED_LIBS=ON
  grep -x "CMAKE_BUILD_TYPE:STRING=Debug" "$dir/CMakeCache.txt"
  cmake --build "$dir"
  ldd "$dir/consumer_c" | grep -F "libpgloss.so.$soversion => $dir/"
  no_werror "$dir"
  run_consumers "$dir"
  installs_nothing "$dir"
}

check version-in-one-place version_in_one_place
for type in static shared; do
  preset=release; [[ $type == shared ]] && preset=shared
  check "install-$type" build_install "$type" "$preset"
  check "installed-files-$type" installed_files "$type"
  check "find_package-$type" find_package_consumer "$type"
  check "pkg-config-$type" pkg_config_consumer "$type"
  check "installed-cli-$type" installed_cli "$type"
done
check find_package-version-rules version_compatibility
check relocated-prefix relocated_prefix
check shared-exports-only-public-api exports
check shared-soname soname
check add_subdirectory subdirectory_consumer
check FetchContent fetchcontent_consumer

echo "== installed files (shared): $(tr '\n' ' ' <"$work/installed-shared.txt")"
echo "== test-package: $passed passed, $failed failed${failures:+ (${failures[*]})}"
((failed == 0))
