# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# CMake toolchain for WebAssembly (wasm32-wasi) with Debian's clang, lld and wasi-libc
# (packages clang lld wasi-libc libclang-rt-14-dev-wasm32). Debian installs wasi-libc as a
# multiarch target under /usr (headers in /usr/include/wasm32-wasi, libraries in
# /usr/lib/wasm32-wasi), which clang finds by itself; a WASI SDK elsewhere is named by
# WASI_SYSROOT (e.g. -DWASI_SYSROOT=/opt/wasi-sdk/share/wasi-sysroot).
list(APPEND CMAKE_MODULE_PATH ${CMAKE_CURRENT_LIST_DIR})  # Platform/WASI.cmake
set(CMAKE_SYSTEM_NAME WASI)
set(CMAKE_SYSTEM_VERSION 1)
set(CMAKE_SYSTEM_PROCESSOR wasm32)
set(_pgloss_wasm_triple wasm32-wasi)

if(NOT CMAKE_C_COMPILER)
  find_program(CMAKE_C_COMPILER NAMES clang clang-14 REQUIRED)
endif()
set(CMAKE_C_COMPILER_TARGET ${_pgloss_wasm_triple})
# GNU ar cannot index wasm objects: the archiver must be LLVM's.
find_program(CMAKE_AR NAMES llvm-ar llvm-ar-14 REQUIRED)
find_program(CMAKE_RANLIB NAMES llvm-ranlib llvm-ranlib-14 REQUIRED)

set(WASI_SYSROOT "" CACHE PATH "wasi-libc sysroot (empty: Debian's multiarch wasi-libc under /usr)")
if(WASI_SYSROOT)
  set(CMAKE_SYSROOT ${WASI_SYSROOT})
endif()

# A static library is what try_compile can build without a WASI runtime to run it.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_EXECUTABLE_SUFFIX ".wasm")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
