// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// The virtual glossmeter's functions of pgloss._core (bind_glossmeter.cpp), added to the module
// by core.cpp.
#pragma once
#include <pybind11/pybind11.h>

namespace pgloss_py {
void bind_glossmeter(pybind11::module_ &mod);
}
