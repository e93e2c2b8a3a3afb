# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""pgloss — the psychophysically-based light reflection model of Pellacini, Ferwerda &
Greenberg, "Toward a Psychophysically-Based Light Reflection Model for Image Synthesis",
SIGGRAPH 2000, for numpy.

The isotropic Ward BRDF (paper eq. 2; ρd, ρs, α) re-expressed in perceptual terms: CIELAB
lightness L*, contrast gloss ``c`` (eq. 4) and distinctness-of-image gloss ``d`` (eq. 3),
with a perceptually uniform gloss distance (eq. 5) and the inverse mapping (eqs. 6–8).

Every function of the C library (``pgloss_eval`` → :func:`pgloss.eval`, …) is here, under
the same name without the prefix. Functions are **array-first**:

* directions are ``(..., 3)`` arrays (normal = +z; ``wo`` towards the viewer, ``wi``
  towards the light; any length, they are normalised), broadcast against each other;
* scalar parameters of the perceptual functions are scalars or arrays of any
  broadcast-compatible shapes;
* :class:`Physical` and :class:`Perceptual` hold one paint or an array of paints (a whole
  texture is one object); :func:`eval`, :func:`pdf`, :func:`eval_pdf` and :func:`sample`
  take such an array (or a list of paints) as one material per element, broadcast against
  the directions;
* the loops run in C with the GIL released, a long array over :func:`get_num_threads` threads
  (default: every CPU this process may run on; :func:`set_num_threads`, ``PGLOSS_NUM_THREADS``)
  with the same results, bit for bit, on any number; a scalar input gives a Python ``float``.

Precision: the BRDF functions (:func:`eval`, :func:`pdf`, :func:`eval_pdf`, :func:`sample`)
run the C core's strided batches (``pgloss_eval_pdf_batch``, ``pgloss_sample_batch``), which
read numpy's arrays in place: ``float32`` arrays the float batch, giving ``float32``;
``float64`` (and integer) arrays the double batch (double arithmetic on the double directions,
the accuracy of the scalar double reference), giving ``float64``. ``out=`` writes the big
outputs into the caller's arrays. The perceptual and colour functions compute in
double (the batched ``pgloss_*_batch`` functions of ``pgloss/perceptual_batch.h`` where the
core has them); their result is ``float32`` for ``float32`` input and ``float64`` otherwise.

Errors are exceptions: :class:`PglossError` (a :class:`ValueError`) carrying the core's
status and reason, the index of the first failing element and, for element-wise calls, the
status of every element (``status_array``). ``errors="status"`` returns the statuses instead
of raising (the conversions and element-wise functions), and ``check()`` of an array of paints
returns them. A conversion's verdict on a paint is the core's check of it (``check=False``: the
bare conversion). Values outside the range the paper trusts (α > 0.2) give an
:class:`AlphaUntrustedWarning`. No function returns NaN or Inf for finite input.

Example:

    >>> import numpy as np, pgloss
    >>> paint = pgloss.Perceptual(L=50.0, a=0.0, b=0.0, c=0.06, d=0.95).to_physical()
    >>> wo = np.array([0.0, 0.3, 1.0]); wi = np.array([[0.0, -0.3, 1.0], [0.5, 0.0, 1.0]])
    >>> pgloss.eval(paint, wo, wi).shape
    (2, 3)
"""

from . import _core
from . import bridge  # the gloss bridge (pgloss/bridge.h)
from . import glossmeter  # the virtual glossmeter (pgloss/glossmeter.h)
from ._brdf import SampleRecord, eval, eval_pdf, material_init, pdf, sample, specular_probability
from ._core import Material
from ._paints import (Perceptual, Physical, check_perceptual, check_physical, perceptual_from_physical,
                      physical_from_perceptual)
from ._perceptual import (contrast_gloss, envelope_contrast, gloss_distance, gloss_from_physical, isogloss_contour,
                          lab_from_rgb, lightness_from_luminance, luminance, luminance_from_lightness, match_gloss,
                          physical_from_gloss, rgb_from_lab, specular_from_contrast)
from ._status import (AlphaUntrustedWarning, ColorSpace, Lobe, Normalization, PglossError, PglossWarning, Status,
                      status_name, status_string)
from ._threads import MAX_THREADS, MIN_ELEMENTS_PER_THREAD, get_num_threads, set_num_threads

__all__ = [
    "__version__", "VERSION", "ALPHA_MIN", "COS_MIN", "CIE_EPSILON", "CIE_KAPPA", "D_WEIGHT",
    "ALPHA_TRUSTED_MAX", "BOUNDARY_TOLERANCE", "LUMA",
    "Status", "Normalization", "ColorSpace", "Lobe", "PglossError", "PglossWarning", "AlphaUntrustedWarning",
    "Physical", "Perceptual", "Material", "SampleRecord",
    "status_string", "status_name",
    "material_init", "specular_probability", "eval", "pdf", "eval_pdf", "sample",
    "lightness_from_luminance", "luminance_from_lightness", "contrast_gloss",
    "specular_from_contrast", "gloss_from_physical", "physical_from_gloss", "gloss_distance",
    "envelope_contrast", "match_gloss", "isogloss_contour", "check_physical",
    "check_perceptual", "physical_from_perceptual", "perceptual_from_physical",
    "rgb_from_lab", "lab_from_rgb", "luminance",
    "set_num_threads", "get_num_threads", "MAX_THREADS", "MIN_ELEMENTS_PER_THREAD",
]

__version__: str = _core.VERSION
VERSION: str = _core.VERSION
#: Smallest α a material uses; smaller positive values are raised to it.
ALPHA_MIN: float = _core.ALPHA_MIN
#: Cosines below this are raised to it inside the specular normalisation.
COS_MIN: float = _core.COS_MIN
#: CIE 1976 ε = 216/24389.
CIE_EPSILON: float = _core.CIE_EPSILON
#: CIE 1976 κ = 24389/27.
CIE_KAPPA: float = _core.CIE_KAPPA
#: Weight of the d axis in the gloss distance (eq. 5): 1.78.
D_WEIGHT: float = _core.D_WEIGHT
#: α above this is outside what the paper trusts (§4): 0.2.
ALPHA_TRUSTED_MAX: float = _core.ALPHA_TRUSTED_MAX
#: Slack of the energy/envelope comparisons.
BOUNDARY_TOLERANCE: float = _core.BOUNDARY_TOLERANCE
#: Rec. 709 luminance weights (r, g, b).
LUMA: tuple[float, float, float] = tuple(_core.LUMA)  # type: ignore[assignment]

# The public objects are pgloss.X wherever they are defined (help(), repr of classes, pickles).
for _name in __all__:
    _obj = globals()[_name]
    if getattr(_obj, "__module__", "").startswith("pgloss._") and _obj is not Material:
        _obj.__module__ = __name__
del _name, _obj
