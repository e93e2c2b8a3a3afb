# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""Stimuli for a stated display: the renderer's linear image tone-mapped and encoded so that the
display shows the luminances the paper's procedure intends (§3.2.3.1–3.2.3.2).

The paper's display: a calibrated monitor of 0.7 to 108 cd/m² with a system gamma of 2.35, images
tone-mapped by Tumblin's rational sigmoid. Here:

1. the scene's own tone map (its ``tonemap exposure limit sharpness`` line, the sigmoid that
   pgloss-tracer applies to its PNG) scales each pixel by Y_out / Y with
   Y_out = s(exposure · Y), s(x) = x / (1 + (x/limit)^n)^(1/n): the relative display luminance
   (1 = the display's white);
2. the display is modelled as L(V) = black + (white − black) · V^γ for a code value V in [0, 1];
   each channel's intended luminance white · Y_rel is produced where the display can
   (V = ((white · Y_rel − black) / (white − black))^(1/γ), clipped to [0, 1]): luminances below
   the black level are lost, those above it are reproduced, the black level's flare included;
3. 8-bit PNG without colour chunks (no gAMA, sRGB or iCCP: browsers then leave the code values
   alone), written with the standard library.

The EXR reader covers what pgloss-tracer writes (OpenImageIO: one part, scan lines, ZIP
compression, FLOAT channels R, G, B) and also NONE/ZIPS compression and HALF/UINT channels.
Specification: "The OpenEXR File Layout" (openexr.com, file version 2).
"""

from __future__ import annotations

import re
import struct
import zlib
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Dict

import numpy as np

from .manifest import SpecError


@dataclass(frozen=True)
class Display:
    """A display's white and black luminance (cd/m²) and gamma; the default is the paper's."""

    white: float = 108.0
    black: float = 0.7
    gamma: float = 2.35

    def __post_init__(self):
        if not (np.isfinite([self.white, self.black, self.gamma]).all() and 0 <= self.black < self.white
                and 0.5 <= self.gamma <= 5):
            raise SpecError(f"display white={self.white} black={self.black} gamma={self.gamma}: want 0 ≤ black < white "
                            "(cd/m²) and gamma in [0.5, 5]")

    @classmethod
    def parse(cls, text: str) -> "Display":
        """'white=108,black=0.7,gamma=2.35' (any subset; the rest the paper's)."""
        values: Dict[str, float] = {}
        for part in filter(None, re.split(r"[,\s]+", text.strip())):
            key, sep, value = part.partition("=")
            if not sep or key not in ("white", "black", "gamma"):
                raise SpecError(f"--display '{text}': want white=CD,black=CD,gamma=G (e.g. white=108,black=0.7,gamma=2.35)")
            try:
                values[key] = float(value)
            except ValueError:
                raise SpecError(f"--display {key}={value!r}: not a number") from None
        return cls(**values)

    def record(self) -> dict:
        return {**asdict(self), "model": "L = black + (white - black) * V^gamma, V in [0, 1]"}


# -- EXR
_PIXEL_BYTES = {0: 4, 1: 2, 2: 4}  # UINT, HALF, FLOAT
_PIXEL_DTYPE = {0: "<u4", 1: "<f2", 2: "<f4"}
_LINES = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP


def _undo_zip(raw: bytes, expected: int) -> bytes:
    t = bytearray(zlib.decompress(raw))
    if len(t) != expected:
        raise ValueError(f"a block decompresses to {len(t)} bytes, not {expected}")
    for i in range(1, len(t)):  # the predictor: each byte stored as the difference to the last + 128
        t[i] = (t[i - 1] + t[i] - 128) & 0xFF
    half = (len(t) + 1) // 2  # interleaved: the even bytes first, then the odd ones
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return bytes(out)


def read_exr(path: Path) -> np.ndarray:
    """The R, G, B channels of a single-part scan-line EXR as a float64 (height, width, 3) array."""
    data = Path(path).read_bytes()
    try:
        if data[:4] != b"\x76\x2f\x31\x01":
            raise ValueError("not an OpenEXR file (magic number)")
        version = struct.unpack_from("<I", data, 4)[0]
        if version & 0xFF != 2 or version & 0x1E00:  # tiled, long names, deep or multi-part
            raise ValueError(f"version field {version:#x}: only single-part scan-line files are read")
        pos, attrs = 8, {}
        while data[pos] != 0:
            end = data.index(0, pos)
            name = data[pos:end].decode()
            tend = data.index(0, end + 1)
            size = struct.unpack_from("<i", data, tend + 1)[0]
            attrs[name] = data[tend + 5:tend + 5 + size]
            pos = tend + 5 + size
        pos += 1
        channels, p = [], 0
        chl = attrs["channels"]
        while chl[p] != 0:
            end = chl.index(0, p)
            channels.append((chl[p:end].decode(), struct.unpack_from("<i", chl, end + 1)[0]))
            p = end + 17  # pixel type, pLinear + 3 reserved, xSampling, ySampling
        compression = attrs["compression"][0]
        x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
        w, h = x1 - x0 + 1, y1 - y0 + 1
        if compression not in _LINES:
            raise ValueError(f"compression {compression}: only NONE, ZIPS and ZIP are read")
        lines = _LINES[compression]
        nblocks = (h + lines - 1) // lines
        offsets = struct.unpack_from(f"<{nblocks}Q", data, pos)
        planes = {name: np.zeros((h, w)) for name, _ in channels}
        for off in offsets:
            y, size = struct.unpack_from("<ii", data, off)
            n = min(lines, y1 - y + 1)
            expected = n * w * sum(_PIXEL_BYTES[t] for _, t in channels)
            block = data[off + 8:off + 8 + size]
            raw = block if compression == 0 or size == expected else _undo_zip(block, expected)
            q = 0
            for row in range(n):
                for name, t in channels:  # per scan line, the channels in the file's (sorted) order
                    count = w * _PIXEL_BYTES[t]
                    planes[name][y - y0 + row] = np.frombuffer(raw, _PIXEL_DTYPE[t], w, q)
                    q += count
    except (ValueError, KeyError, IndexError, struct.error, zlib.error, UnicodeDecodeError) as e:
        raise SpecError(f"{path}: cannot read the EXR image ({e})") from None
    if not {"R", "G", "B"} <= set(planes):
        raise SpecError(f"{path}: want channels R, G, B (has {sorted(planes)})")
    return np.stack([planes["R"], planes["G"], planes["B"]], axis=-1)


# -- tone map and encoding
def scene_tonemap(scene_text: str) -> Dict[str, float]:
    """The scene's ``tonemap`` line (pgloss-tracer's defaults where a key or the line is absent)."""
    out = {"exposure": 1.0, "limit": 1.0, "sharpness": 2.0}
    for line in scene_text.splitlines():
        words = line.split("#")[0].split()
        if words[:1] == ["tonemap"]:
            for w in words[1:]:
                k, _, v = w.partition("=")
                if k in out:
                    out[k] = float(v)
    return out


def encode(linear: np.ndarray, tonemap: Dict[str, float], display: Display) -> np.ndarray:
    """The 8-bit code values (height, width, 3) that show the linear image on the display."""
    rgb = np.maximum(np.asarray(linear, dtype=np.float64), 0.0)
    y = rgb @ np.array([0.2126, 0.7152, 0.0722])  # Rec. 709 luminance (the renderer's primaries)
    x = tonemap["exposure"] * y
    n = tonemap["sharpness"]
    with np.errstate(divide="ignore", invalid="ignore"):
        s = x / (1.0 + (x / tonemap["limit"]) ** n) ** (1.0 / n)
        k = np.where(x > 0, s / np.where(x > 0, y, 1.0), 0.0)
    rel = np.minimum(rgb * k[..., None], 1.0)
    v = np.clip((display.white * rel - display.black) / (display.white - display.black), 0.0, 1.0) ** (1.0 / display.gamma)
    return np.rint(v * 255.0).astype(np.uint8)


def write_png(path: Path, rgb: np.ndarray) -> None:
    """An 8-bit RGB PNG (no colour chunks), through a temporary file renamed into place."""
    rgb = np.ascontiguousarray(rgb, dtype=np.uint8)
    h, w, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[r].tobytes() for r in range(h))  # filter 0 on every line

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    tmp = Path(path).with_name(f".{Path(path).name}.tmp")
    tmp.write_bytes(png)
    tmp.replace(path)

