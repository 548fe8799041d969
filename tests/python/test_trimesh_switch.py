"""geomquery.trimesh: trimesh's ray and proximity API, answered by gq, against brute force in numpy."""

import numpy as np
import pytest

import geomquery as gq
import geomquery.trimesh as gtm
from conftest import brute_point_distance, brute_rays, cube_mesh, icosphere


class Mesh:
    """What the switch reads of a trimesh.Trimesh: vertices and faces."""

    def __init__(self, vertices, faces):
        self.vertices, self.faces = vertices, faces


@pytest.fixture
def sphere():
    return Mesh(*icosphere(2))


def rays(n, seed=2):
    rng = np.random.default_rng(seed)
    origins = rng.uniform(-2, 2, (n, 3))
    dirs = rng.normal(size=(n, 3)) * 3.0  # not unit: the switch normalises, as trimesh does
    return origins, dirs


def test_trimesh_style_session(sphere):
    ray = gtm.RayMeshIntersector(sphere)
    origins, dirs = rays(200)
    unit = dirs / np.linalg.norm(dirs, axis=1)[:, None]
    brute = brute_rays(sphere.vertices, sphere.faces, origins, unit)

    first = ray.intersects_first(origins, dirs)
    assert first.shape == (200,) and first.dtype == np.int64
    for r in range(200):
        mine = [(t, i) for rr, i, t in brute if rr == r]
        if not mine:
            assert first[r] == -1
        else:
            t, _ = min(mine)
            # The reported triangle is hit at the nearest distance (ties on shared edges may pick either).
            assert any(abs(tt - t) < 1e-9 and i == first[r] for tt, i in mine)
    assert np.array_equal(ray.intersects_any(origins, dirs), first >= 0)

    index_tri, index_ray = ray.intersects_id(origins, dirs)
    assert index_tri.dtype == np.int64 and index_ray.dtype == np.int64
    counts = np.bincount(index_ray, minlength=200)
    brute_counts = np.bincount([r for r, _, _ in brute], minlength=200)
    assert np.array_equal(counts, brute_counts)

    locations, index_ray2, index_tri2 = ray.intersects_location(origins, dirs)
    assert locations.shape == (len(index_ray2), 3)
    assert np.allclose(np.linalg.norm(locations, axis=1), 1.0, atol=0.05)  # on the sphere-like surface
    tri, ray_ids, loc = ray.intersects_id(origins, dirs, multiple_hits=False, return_locations=True)
    assert np.array_equal(ray_ids, np.nonzero(first >= 0)[0]) and np.array_equal(tri, first[first >= 0])
    assert loc.shape == (len(ray_ids), 3)

    points = np.random.default_rng(4).uniform(-1.5, 1.5, (100, 3))
    inside = ray.contains_points(points)
    radius = np.linalg.norm(points, axis=1)
    clear = np.abs(radius - 0.99) > 0.03  # away from the faceted surface
    assert np.array_equal(inside[clear], (radius < 0.99)[clear])


def test_proximity_query_matches_brute_force(sphere):
    prox = gtm.ProximityQuery(sphere)
    points = np.random.default_rng(8).uniform(-1.5, 1.5, (40, 3))
    closest, distance, triangle = prox.on_surface(points)
    assert closest.shape == (40, 3) and distance.shape == (40,) and triangle.dtype == np.int64
    for i, p in enumerate(points):
        assert distance[i] == pytest.approx(brute_point_distance(sphere.vertices, sphere.faces, p), abs=1e-9)
    signed = prox.signed_distance(points)
    inside = np.linalg.norm(points, axis=1) < 0.95
    outside = np.linalg.norm(points, axis=1) > 1.0
    assert np.all(signed[inside] > 0) and np.all(signed[outside] < 0)  # trimesh's sign: positive inside
    assert np.allclose(np.abs(signed), distance)
    d, vid = prox.vertex(points)
    assert np.allclose(d, np.linalg.norm(sphere.vertices[vid] - points, axis=1))


def test_cooked_once_and_shared():
    v, f = cube_mesh()
    a, b = Mesh(v, f), Mesh(v.copy(), f.copy())
    assert gtm.cooked_mesh(a) is gtm.cooked_mesh(b)
    ray = gtm.RayMeshIntersector(a)
    ray.intersects_first(np.zeros((1, 3)), np.ones((1, 3)))
    assert ray._cooked is gtm.ProximityQuery(b)._gq


def test_rays_of_any_layout_answer_as_normalized_contiguous_rays(sphere):
    ray = gtm.RayMeshIntersector(sphere)
    origins, dirs = rays(300, seed=6)
    unit = np.ascontiguousarray(dirs / np.linalg.norm(dirs, axis=1)[:, None])
    expected = gq.raycast_batch_faces(origins, unit, gtm.cooked_mesh(sphere).mesh, None, float("inf"), True)
    assert np.array_equal(ray.intersects_first(origins, dirs), expected)
    both = np.hstack([origins, dirs])
    assert np.array_equal(ray.intersects_first(both[:, :3], both[:, 3:]), expected)  # row-strided views
    assert np.array_equal(ray.intersects_first(np.asfortranarray(origins), np.asfortranarray(dirs)), expected)
    assert np.array_equal(ray.intersects_first(origins[::-1], dirs[::-1]), expected[::-1])
    assert np.array_equal(ray.intersects_first(origins.tolist(), dirs.tolist()), expected)
    o32, d32 = origins.astype(np.float32), dirs.astype(np.float32)
    unit32 = o32.astype(np.float64), d32 / np.linalg.norm(d32.astype(np.float64), axis=1)[:, None]
    assert np.array_equal(ray.intersects_first(o32, d32),
                          gq.raycast_batch_faces(*unit32, gtm.cooked_mesh(sphere).mesh, None, float("inf"), True))


def test_bad_inputs_raise():
    with pytest.raises(TypeError, match="vertices"):
        gtm.RayMeshIntersector(object()).intersects_first(np.zeros((1, 3)), np.ones((1, 3)))
    with pytest.raises(ValueError, match="no faces"):
        gtm.RayMeshIntersector(Mesh(np.zeros((3, 3)), np.zeros((0, 3), dtype=np.int64))).intersects_any(
            np.zeros((1, 3)), np.ones((1, 3)))
    ray = gtm.RayMeshIntersector(Mesh(*cube_mesh()))
    with pytest.raises(ValueError, match="shape"):
        ray.intersects_first(np.zeros((2, 3)), np.ones((3, 3)))
    with pytest.raises(ValueError, match="zero-length"):
        ray.intersects_first(np.zeros((1, 3)), np.zeros((1, 3)))
    with pytest.raises(ValueError, match="item 0"):
        ray.intersects_first(np.full((1, 3), np.nan), np.ones((1, 3)))
