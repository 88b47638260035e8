#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Final length, footprint diameter and outline of a Taylor bar from a gsph-solve snapshot.

Each particle stands for its cell: the reference half-edges e_d are half the step from the
centre of the cell's −d face to that of its +d face, from the cell's corners in /spaces/nodes
(for a file without them, central differences of X over the particle's lattice neighbours in
its home space: one-sided at a space's boundary, wrapped on periodic indices, and short of the
cell on graded lattices), the deformed half-edges are F e_d, and the
particle's cell reaches n·x + Σ_d |n·F e_d| along a direction n. The bar's length is the
distance between its highest and lowest reach along z (the axis). The footprint diameter is
that of the disc of the impact face's area: the particles of the set "impact" (the face z = 0)
carry their cells' bottom faces, of reference area vector A0 = 4 e_1 × e_2 (the two half-edges
across z) and current area vector J F^-T A0 (Nanson); D = 2 √(Σ |A_z| / π). A 2-D (axisymmetric)
particle file is measured the same way on its section: y the axis, each cell a ring, the
footprint the rings the impact face's cells sweep. Also: the plastic strain and temperature of
the impact face's particle nearest the axis (the face centre), and their means over the face's
centre region (CENTRE_REGION: where a finite-element reference's centre element lies). An area
measure is fair to both layouts: a staircase's corners would inflate a largest-radius measure by
up to h(√2 − 1), the O-grid's polygon would shrink it.

    taylor.py PARTICLES.h5 SNAPSHOT.h5     prints length and footprint [mm]
"""
import sys

import h5py
import numpy as np

# The copper rod's (190 m/s, 80 µs) converged reference [m, m, 1]: docs/validation.md, "Taylor
# bar, axisymmetric": length and footprint from the graded sections' refinement series, the
# plastic strain over the impact face's centre region (below) from the square sections'. One
# particle's strain at the axis does not converge (docs/theory.md "The face centre's plastic
# strain").
CONVERGED_COPPER = {"length": 17.392e-3, "footprint": 14.777e-3, "region_strain": 2.666}

# The impact face's centre as a region, the way a finite-element reference samples it: the
# centre element of an axisymmetric mesh of 5 x 50 elements spans r < R0/5 and the first L0/50
# of the rod. A mean over a fixed region of the reference configuration is a converged quantity
# where one particle's value next to the axis is not (docs/theory.md "The face centre's plastic
# strain").
CENTRE_REGION = (1.0 / 5.0, 1.0 / 50.0)  # (radius / R0, height / L0)


def half_edges(particles_h5):
    """Reference half-edge vectors, shape (N, 3 axes, 3 components), the impact set and the
    file's dimension (2: an axisymmetric section, x the radius and y the axis)."""
    with h5py.File(particles_h5, "r") as f:
        dimension = int(f["dimension"][0]) if "dimension" in f else 3
        X = f["particles/X"][...]
        ijk = f["particles/lattice_index"][...].astype(np.int64)
        space = f["particles/space"][...].astype(np.int64)
        cells = f["spaces/cells"][...].astype(np.int64)
        periodic = f["spaces/periodic"][...].astype(bool)
        impact = f["sets/impact"][...].astype(np.int64)
        nodes = f["spaces/nodes"][...] if "spaces/nodes" in f else None
    if nodes is not None:
        return corner_edges(nodes, ijk, space, cells, periodic, dimension), impact, dimension
    n = len(X)
    # One integer key per (space, i, j, k): index into a dense table per space.
    offset = np.concatenate([[0], np.cumsum(np.prod(cells, axis=1))])
    table = -np.ones(offset[-1], dtype=np.int64)

    def key(s, c):
        return offset[s] + c[:, 0] + cells[s, 0] * (c[:, 1] + cells[s, 1] * c[:, 2])

    table[key(space, ijk)] = np.arange(n)
    edges = np.zeros((n, 3, 3))
    for d in range(dimension):
        found = []
        for step in (+1, -1):
            c = ijk.copy()
            c[:, d] += step
            wrap = periodic[space, d]
            c[wrap, d] %= cells[space[wrap], d]
            inside = (c[:, d] >= 0) & (c[:, d] < cells[space, d])
            nb = -np.ones(n, dtype=np.int64)
            nb[inside] = table[key(space[inside], c[inside])]
            found.append(nb)
        up, down = found
        both = (up >= 0) & (down >= 0)
        only_up = (up >= 0) & (down < 0)
        only_down = (down >= 0) & (up < 0)
        e = np.zeros((n, 3))
        e[both] = 0.25 * (X[up[both]] - X[down[both]])
        e[only_up] = 0.5 * (X[up[only_up]] - X[only_up])
        e[only_down] = 0.5 * (X[only_down] - X[down[only_down]])
        edges[:, d, :] = e
    return edges, impact, dimension


def corner_edges(nodes, ijk, space, cells, periodic, dimension):
    """Half-edges of each particle's cell from its corners (/spaces/nodes: per space, m_d = n_d + 1
    nodes along index d, n_d along a periodic one; i fastest): e_d is half the step between the
    centres of the cell's faces across d, exact for any hexahedron (quadrangle on a section)."""
    extent = cells + np.where(periodic, 0, 1)
    first = np.concatenate([[0], np.cumsum(np.prod(extent, axis=1))])
    m = extent[space]  # (N, 3)
    layers = (0, 1) if dimension == 3 else (0,)  # a section's slab: its k = 0 layer
    corners = {}
    for a in (0, 1):
        for b in (0, 1):
            for c in layers:
                idx = ijk + np.array([a, b, c])
                idx = np.where(periodic[space], idx % m, idx)
                at = first[space] + idx[:, 0] + m[:, 0] * (idx[:, 1] + m[:, 1] * idx[:, 2])
                corners[a, b, c] = nodes[at]
    edges = np.zeros((len(ijk), 3, 3))
    for d in range(dimension):
        # ½ (mean of the +d corners − mean of the −d corners)
        step = sum(x if key[d] == 1 else -x for key, x in corners.items())
        edges[:, d, :] = step / len(corners)
    return edges


def centre_region(particles_h5, edges, dimension, samples=8):
    """The reference cells' overlap with the centre region (CENTRE_REGION): (particle indices,
    weights summing to 1). Each cell X + Σ s_d e_d, s in [-1, 1]^dim, is sampled at samples^dim
    midpoints, each of volume |det e| (times 2π r on a section: the ring)."""
    with h5py.File(particles_h5, "r") as f:
        X = f["particles/X"][...]
    axis = 1 if dimension == 2 else 2
    radial = [0] if dimension == 2 else [0, 1]
    reach = np.abs(edges).sum(axis=1)  # (N, component): the cell's reach from its centre
    r = np.linalg.norm(X[:, radial], axis=1)
    bottom = np.min(X[:, axis] - reach[:, axis])
    L0 = np.max(X[:, axis] + reach[:, axis]) - bottom
    # The rod's radius from its volume: a uniform staircase's corners and an O-grid's polygon
    # give the same R0 as the round rod they stand for.
    cells = 2.0**dimension * np.abs(np.linalg.det(edges[:, :dimension, :dimension]))
    rod_volume = np.sum(cells * 2.0 * np.pi * r) if dimension == 2 else np.sum(cells)
    R0 = np.sqrt(rod_volume / (np.pi * L0))
    rmax, zmax = CENTRE_REGION[0] * R0, bottom + CENTRE_REGION[1] * L0
    near = np.flatnonzero((r - np.linalg.norm(reach[:, radial], axis=1) < rmax)
                          & (X[:, axis] - reach[:, axis] < zmax))
    s = (np.arange(samples) + 0.5) / samples * 2.0 - 1.0
    grid = np.stack(np.meshgrid(*([s] * dimension), indexing="ij"), axis=-1).reshape(-1, dimension)
    e = edges[near][:, :dimension, :]  # (n, d, component)
    points = X[near][:, None, :] + np.einsum("sd,adi->asi", grid, e)
    volume = np.abs(np.linalg.det(e[:, :, :dimension]))[:, None] * np.ones(len(grid))
    pr = np.linalg.norm(points[:, :, radial], axis=2)
    if dimension == 2:
        volume = volume * 2.0 * np.pi * pr
    inside = (pr < rmax) & (points[:, :, axis] < zmax)
    w = (volume * inside).sum(axis=1)
    keep = w > 0
    return near[keep], w[keep] / w.sum()


def measure(particles_h5, snapshot_h5, layout=None, region=None):
    edges, impact, dimension = layout if layout is not None else half_edges(particles_h5)
    if region is None:
        region = centre_region(particles_h5, edges, dimension)
    with h5py.File(snapshot_h5, "r") as f:
        x = f["particles/x"][...]
        F = f["particles/F"][...].reshape(-1, 3, 3)
        time = float(f["time"][()])
        strain = f["particles/plastic_strain"][...] if "particles/plastic_strain" in f else None
        temperature = f["particles/temperature"][...] if "particles/temperature" in f else None
    deformed = np.einsum("aij,adj->adi", F, edges)  # F e_d, (N, axis d, component i)
    if dimension == 2:
        axis, r = 1, x[:, 0]
        reach_r = r + np.abs(deformed[:, :, 0]).sum(axis=1)
        area = ring_area(x, deformed, impact)
    else:
        axis, r = 2, np.hypot(x[:, 0], x[:, 1])
        rhat = np.zeros_like(x)
        nz = r > 0
        rhat[nz, 0] = x[nz, 0] / r[nz]
        rhat[nz, 1] = x[nz, 1] / r[nz]
        reach_r = r + np.abs(np.einsum("adi,ai->ad", deformed, rhat)).sum(axis=1)
        area = face_area(edges, F, impact)
    reach_z = np.abs(deformed[:, :, axis]).sum(axis=1)
    top = np.max(x[:, axis] + reach_z)
    bottom = np.min(x[:, axis] - reach_z)
    widest = int(np.argmax(reach_r))
    centre = impact[np.argmin(r[impact])]
    return {
        "time": time,
        "length": top - bottom,
        "footprint": 2.0 * np.sqrt(area / np.pi),
        "widest": 2.0 * reach_r[widest],
        "at_z": x[widest, axis] - bottom,
        "bottom": bottom,
        "z": x[:, axis] - bottom,
        "reach_z": reach_z,
        "reach_r": reach_r,
        "centre_strain": strain[centre] if strain is not None else np.nan,
        "centre_temperature": temperature[centre] if temperature is not None else np.nan,
        "region_strain": region[1] @ strain[region[0]] if strain is not None else np.nan,
        "region_temperature": region[1] @ temperature[region[0]]
        if temperature is not None else np.nan,
    }


def face_area(edges, F, impact):
    """3-D: Σ |A_z| of the impact face's cells' bottom faces, J F^-T A0 (Nanson)."""
    # Per particle, the axis most aligned with z is the one across the face.
    e = edges[impact]
    across = np.argmax(np.abs(e[:, :, 2]), axis=1)
    first = np.where(across == 0, 1, 0)
    second = np.where(across == 2, 1, 2)
    rows = np.arange(len(impact))
    A0 = 4.0 * np.cross(e[rows, first], e[rows, second])
    Fi = F[impact]
    cofactor = np.linalg.det(Fi)[:, None, None] * np.linalg.inv(Fi).transpose(0, 2, 1)
    return np.abs(np.einsum("aij,aj->ai", cofactor, A0)[:, 2]).sum()


def ring_area(x, deformed, impact):
    """Axisymmetric section (x = r, y the axis): the rings the impact face's cells sweep,
    Σ 2π r |radial width| of their faces on y = 0."""
    e = deformed[impact]
    along = np.argmax(np.abs(e[:, :2, 0]), axis=1)  # the in-plane edge that runs radially
    width = 2.0 * np.abs(e[np.arange(len(impact)), along, 0])
    return (2.0 * np.pi * x[impact, 0] * width).sum()


def outline(m, points=200):
    """The bar's profile (z, r): at each height, the largest radial reach of the cells that
    span it (a cell spans z_a ± its reach along z)."""
    z, dz, r = m["z"], m["reach_z"], m["reach_r"]
    zs = np.linspace(0.0, m["length"], points)
    rs = np.array([r[np.abs(z - zc) <= dz].max(initial=0.0) for zc in zs])
    return zs[rs > 0], rs[rs > 0]


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: taylor.py PARTICLES.h5 SNAPSHOT.h5")
    m = measure(sys.argv[1], sys.argv[2])
    print(f"t = {m['time']:.3e} s: length {1e3 * m['length']:.3f} mm, footprint diameter "
          f"{1e3 * m['footprint']:.3f} mm (largest reach: {1e3 * m['widest']:.3f} mm at "
          f"z = {1e3 * m['at_z']:.3f} mm); impact-face centre: plastic strain "
          f"{m['centre_strain']:.3f}, temperature {m['centre_temperature']:.1f} K; over its "
          f"centre region (r < R0/5, the first L0/50): plastic strain {m['region_strain']:.3f}, "
          f"temperature {m['region_temperature']:.1f} K")
