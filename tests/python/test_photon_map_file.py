"""kdpm.PhotonMapFile: k nearest like SciPy's cKDTree, the surface filter and the radiance
estimate against NumPy references, zero-copy arrays, bad input."""
import gc

import numpy as np
import pytest
from scipy.spatial import cKDTree

import kdpm
from conftest import PHOTONS
from reference_math import filtered_knn


def query_points(photons, n, seed):
    """Points near the photons (a photon moved a little), as gathers query them."""
    rng = np.random.default_rng(seed)
    positions = photons.positions()
    picks = positions[rng.integers(0, len(positions), n)]
    return (picks + rng.normal(scale=0.02, size=picks.shape)).astype(np.float32)


def assert_same_neighbours(d, i, d_ref, i_ref):
    """d_ref, i_ref: k + 1 neighbours, to see whether the k-th is clear of the next one."""
    k = d.shape[1]
    np.testing.assert_allclose(d, d_ref[:, :k], rtol=1e-5, atol=1e-6)
    # Where the k-th and (k+1)-th distances are not within rounding, the same k photons.
    clear = d_ref[:, k] - d_ref[:, k - 1] > 1e-5 * (1 + d_ref[:, k])
    assert np.mean(clear) > 0.9
    assert np.array_equal(np.sort(i[clear], axis=1), np.sort(i_ref[clear, :k], axis=1))


@pytest.mark.parametrize("k", [1, 8, 32])
def test_knn_equals_ckdtree(photons, k):
    positions = photons.positions()
    points = query_points(photons, 1500, seed=k)
    points = points[np.lexsort(points.T)]  # neighbouring queries near each other, as a frame's are
    d, i = photons.knn(points, k)
    assert d.shape == (1500, k) and i.shape == (1500, k) and d.dtype == np.float32 and i.dtype == np.int64
    d_ref, i_ref = cKDTree(positions.astype(np.float64)).query(points.astype(np.float64), k + 1)
    assert_same_neighbours(d, i, d_ref, i_ref)
    assert np.all(np.diff(d, axis=1) >= 0)


def test_knn_within_a_radius_fills_like_ckdtree(photons):
    positions = photons.positions()
    points = query_points(photons, 500, seed=7)
    radius = 0.05
    d, i = photons.knn(points, 16, max_radius=radius)
    d_ref, i_ref = cKDTree(positions).query(points, 16, distance_upper_bound=radius)
    missing = np.isinf(d_ref)
    # Photons at the radius itself (within rounding) may count on either side.
    edge = np.abs(np.where(missing, radius, d_ref) - radius) < 1e-5
    agree = ~np.any(edge, axis=1)
    assert np.array_equal(np.isinf(d)[agree], missing[agree])
    assert np.all(i[np.isinf(d)] == photons.photon_count)
    np.testing.assert_allclose(d[agree][~missing[agree]], d_ref[agree][~missing[agree]], rtol=1e-5)


def scattered_and_walking_queries(positions, normals, rng):
    """Queries at random photons, then a walk in small steps across one photon's surface (where
    each search starts from the radii of the ones before)."""
    picks = rng.integers(0, len(positions), 150)
    scattered = positions[picks] + rng.normal(scale=0.01, size=(150, 3)).astype(np.float32)
    start, n = positions[picks[0]], normals[picks[0]]
    tangent = np.cross(n, [0.0, 0.0, 1.0] if abs(n[2]) < 0.9 else [1.0, 0.0, 0.0])
    tangent /= np.linalg.norm(tangent)
    walk = start + np.linspace(-0.05, 0.05, 100)[:, None] * tangent
    points = np.concatenate([scattered, walk]).astype(np.float32)
    surface = np.concatenate([normals[picks], np.tile(n, (100, 1))]).astype(np.float32)
    return points, surface


def test_knn_with_normals_keeps_the_photons_that_may_light_the_surface(photons):
    positions, incoming, normals = photons.positions(), photons.incoming(), photons.normals()
    points, surface = scattered_and_walking_queries(positions, normals, np.random.default_rng(11))
    d, i = photons.knn(points, 16, normals=surface)
    assert np.all(np.isfinite(d[150:]))  # the walk stays on a lit surface
    for q in range(len(points)):
        d_ref, i_ref = filtered_knn(positions, incoming, normals, points[q].astype(np.float64), surface[q], 16)
        n = len(d_ref)
        np.testing.assert_allclose(d[q, :n], d_ref, rtol=1e-5, atol=1e-6)
        assert np.all(np.isinf(d[q, n:]))
        if n > 1 and np.all(np.diff(d_ref) > 1e-5):
            assert set(i[q, :n]) == set(i_ref)


def test_radiance_is_the_photon_estimate_of_the_filtered_neighbours(photons):
    positions, incoming, normals, power = photons.positions(), photons.incoming(), photons.normals(), photons.power()
    rng = np.random.default_rng(13)
    picks = rng.integers(0, len(positions), 100)
    points = positions[picks]
    surface = normals[picks]
    k, albedo = 24, np.array([0.5, 0.7, 0.9])
    radiance = photons.radiance(points, surface, k=k, albedo=albedo.tolist())
    assert radiance.shape == (100, 3) and np.all(radiance >= 0)
    for q in range(len(points)):
        d_ref, i_ref = filtered_knn(positions, incoming, normals, points[q].astype(np.float64), surface[q], k)
        if len(d_ref) < k:
            continue
        expected = albedo / np.pi * power[i_ref].sum(axis=0) / (np.pi * d_ref[-1] ** 2)
        np.testing.assert_allclose(radiance[q], expected, rtol=2e-3)


def test_arrays_are_read_only_views_of_the_mapping(cornell):
    p = kdpm.PhotonMapFile(cornell["kdp"])
    x = p.x
    assert x.base is p and not x.flags.writeable and x.dtype == np.float32
    assert len(x) == p.photon_count == p.info["photon_count"]
    assert p.global_map.x.base is p
    with pytest.raises(ValueError):
        x[0] = 0.0
    assert np.array_equal(np.stack([p.x, p.y, p.z], axis=1), p.positions())
    bounces = (p.flags >> 8) & 0xFF
    assert bounces.max() <= p.info["max_bounces"]
    assert p.emitted_count == PHOTONS
    caustic = p.caustic_map
    if caustic is not None:
        assert np.all(caustic.flags & 1 == 1)
    before = x.copy()
    del p
    gc.collect()
    assert np.array_equal(x, before)


@pytest.mark.parametrize("k", [0, -1, 257])
def test_k_out_of_range_raises(photons, k):
    with pytest.raises(ValueError):
        photons.knn(np.zeros((1, 3), np.float32), k)


def test_bad_queries_raise(photons):
    with pytest.raises(ValueError):
        photons.knn(np.zeros((3,), np.float32), 4)
    with pytest.raises(ValueError):
        photons.knn(np.full((2, 3), np.nan, np.float32), 4)
    with pytest.raises(TypeError):
        photons.knn(np.zeros((2, 3), np.int64), 4)
    with pytest.raises(ValueError):
        photons.knn(np.zeros((2, 3), np.float32), 4, normals=np.zeros((2, 3), np.float32))
    with pytest.raises(ValueError):
        photons.knn(np.zeros((2, 3), np.float32), 4, normals=np.ones((3, 3), np.float32))
    with pytest.raises(ValueError):
        photons.knn(np.zeros((2, 3), np.float32), 4, max_radius=-1.0)
    with pytest.raises(ValueError):
        photons.radiance(np.zeros((2, 3), np.float32), np.ones((2, 3), np.float32), albedo=2.0)


def test_truncated_photon_file_raises(cornell, tmp_path):
    data = cornell["kdp"].read_bytes()
    for cut in (16, len(data) // 3, len(data) - 1):
        path = tmp_path / f"cut{cut}.kdp"
        path.write_bytes(data[:cut])
        with pytest.raises(kdpm.FormatError):
            kdpm.PhotonMapFile(path)
    with pytest.raises(kdpm.FormatError):
        kdpm.PhotonMapFile(cornell["kdg"])
