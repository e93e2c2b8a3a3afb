# SPDX-FileCopyrightText: 2026 The pgloss authors
# SPDX-License-Identifier: Apache-2.0
"""The paper's worked example (§3.2.2): Table 1's distances between ten U.S. cities, and the
cities' true positions to check Fig. 2 against.

Table 1 holds great-circle ("flying") mileages (see ``data/README.md``), i.e. distances on a
sphere, which no plane reproduces exactly. The reference map is the cities' latitude and
longitude in the azimuthal equidistant projection centred on their mean position: it keeps
every distance from the centre exact and distorts the others by at most a few per cent over
the continental U.S. (x east, y north, miles).
"""

from __future__ import annotations

import csv
from importlib import resources
from typing import List, Tuple

import numpy as np

from .proximity import read_csv

#: Mean Earth radius in statute miles (IUGG 6371.0 km).
EARTH_RADIUS_MI = 6371.0 / 1.609344


def _data(name: str):
    return resources.files(__package__).joinpath("data").joinpath(name)


def table1() -> Tuple[np.ndarray, List[str]]:
    """Table 1 as a symmetric (10, 10) array in miles, and the city names (its column order)."""
    with resources.as_file(_data("us_cities.csv")) as path:
        d, w, names = read_csv(path)
    return d, names


def latlon() -> Tuple[np.ndarray, List[str]]:
    """The cities' (latitude, longitude) in degrees, (10, 2), in Table 1's order, and the names."""
    with _data("us_cities_latlon.csv").open("r", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    names = [r["city"] for r in rows]
    return np.array([[float(r["latitude_deg"]), float(r["longitude_deg"])] for r in rows]), names


def great_circle(ll: np.ndarray, radius: float = EARTH_RADIUS_MI) -> np.ndarray:
    """Haversine distances (n, n) between points (n, 2) of latitude, longitude in degrees."""
    lat, lon = np.radians(ll[:, 0]), np.radians(ll[:, 1])
    a = (np.sin((lat[:, None] - lat[None]) / 2) ** 2
         + np.cos(lat[:, None]) * np.cos(lat[None]) * np.sin((lon[:, None] - lon[None]) / 2) ** 2)
    return 2.0 * radius * np.arcsin(np.sqrt(np.clip(a, 0.0, 1.0)))


def azimuthal_equidistant(ll: np.ndarray, radius: float = EARTH_RADIUS_MI) -> np.ndarray:
    """Projects (n, 2) latitude/longitude (degrees) to (n, 2) x east / y north in miles,
    azimuthal equidistant about the points' spherical mean (Snyder 1987, eqs. 25-2 to 25-4)."""
    lat, lon = np.radians(ll[:, 0]), np.radians(ll[:, 1])
    v = np.column_stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)]).mean(axis=0)
    lat0, lon0 = np.arctan2(v[2], np.hypot(v[0], v[1])), np.arctan2(v[1], v[0])
    dl = lon - lon0
    cosc = np.clip(np.sin(lat0) * np.sin(lat) + np.cos(lat0) * np.cos(lat) * np.cos(dl), -1.0, 1.0)
    c = np.arccos(cosc)
    k = np.where(c > 1e-12, c / np.sin(np.where(c > 1e-12, c, 1.0)), 1.0)
    x = radius * k * np.cos(lat) * np.sin(dl)
    y = radius * k * (np.cos(lat0) * np.sin(lat) - np.sin(lat0) * np.cos(lat) * np.cos(dl))
    return np.column_stack([x, y])
