# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
# PGLOSS_CLI_SOURCES: the pgloss tool's commands and their shared helpers (all but main), for
# the tool (tools/CMakeLists.txt), its test (tests/) and its fuzzer (tests/fuzz/).
file(GLOB PGLOSS_CLI_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/cmd_*.c)
list(SORT PGLOSS_CLI_SOURCES)
list(PREPEND PGLOSS_CLI_SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_common.c)
