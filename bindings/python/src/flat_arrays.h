// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Flat float64 inputs of the element-by-element bindings (bind_glossmeter.cpp, bridge.cpp):
// the Python modules broadcast and flatten, so the binding only checks that they agree.
#ifndef PGLOSS_PY_FLAT_ARRAYS_H
#define PGLOSS_PY_FLAT_ARRAYS_H

#include <pybind11/numpy.h>

#include <initializer_list>
#include <stdexcept>

namespace pgloss_py {

using darr = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// The flat inputs' common length (all must be 1-D and equally long).
inline pybind11::ssize_t common_length(std::initializer_list<const darr *> in) {
    pybind11::ssize_t n = -1;
    for (const darr *a : in) {
        if (a->ndim() != 1 || (n >= 0 && a->size() != n))
            throw std::invalid_argument("pgloss._core: inputs must be flat arrays of equal length");
        n = a->size();
    }
    return n;
}

}  // namespace pgloss_py

#endif
