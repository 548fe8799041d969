"""geomquery.urdf on the shared robots and geomquery.trimesh on the shared meshes (skipped, naming the path, when the
shared data folder does not hold them)."""

import os

import numpy as np
import pytest

import geomquery as gq
import geomquery.trimesh as gtm
import geomquery.urdf as gurdf
from conftest import require_shared


def load_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                idx = [int(p.split("/")[0]) - 1 for p in parts[1:]]
                for k in range(1, len(idx) - 1):
                    faces.append([idx[0], idx[k], idx[k + 1]])
    return np.array(vertices), np.array(faces, dtype=np.int64)


@pytest.fixture(scope="module")
def panda():
    robots = require_shared("robots", "example-robot-data", "robots")
    urdf = os.path.join(robots, "panda_description", "urdf", "panda.urdf")
    srdf = os.path.join(robots, "panda_description", "srdf", "panda.srdf")
    return gurdf.Robot(urdf, srdf, mode="hull", package_paths=[require_shared("robots")])


def test_robot_check_batch_equals_check(panda):
    assert len(panda.variables) >= 7
    rng = np.random.default_rng(0)
    limits = np.array(panda.limits)
    Q = rng.uniform(limits[:, 0], limits[:, 1], (400, len(limits)))
    batch = panda.check_batch(Q)
    assert batch.dtype == bool and batch.shape == (400,)
    single = np.array([panda.check(q) for q in Q])
    assert np.array_equal(batch, single)
    assert np.array_equal(panda.check_batch(Q, threads=1), single)
    assert 0 < single.sum() < 400  # random configurations: some collide, some do not
    q = Q[np.argmax(single)]
    pairs = panda.colliding_pairs(q)
    assert pairs and all(a in panda.links and b in panda.links for a, b in pairs)
    d, (a, b), pa, pb = panda.self_distance(Q[np.argmin(single)])
    assert d > 0 and np.linalg.norm(pa - pb) == pytest.approx(d, rel=1e-6)
    assert panda.self_distance(q)[0] <= 0


def test_robot_errors(panda):
    with pytest.raises(ValueError):
        panda.check(np.zeros(2))
    with pytest.raises(ValueError, match="item 1 .*not finite"):
        panda.check_batch(np.vstack([panda.home, np.full(len(panda.variables), np.nan)]))
    with pytest.raises(FileNotFoundError):
        gurdf.Robot("/nonexistent/robot.urdf")
    with pytest.raises(ValueError, match="representation"):
        gurdf.Robot("/nonexistent/robot.urdf", mode="blob")


def test_bunny_rays_and_proximity_match_single_queries():
    v, f = load_obj(require_shared("meshes", "stanford-bunny.obj"))

    class Mesh:
        vertices, faces = v, f

    ray = gtm.RayMeshIntersector(Mesh())
    lo, hi = v.min(axis=0), v.max(axis=0)
    rng = np.random.default_rng(9)
    origins = rng.uniform(lo - 0.1, hi + 0.1, (500, 3))
    dirs = rng.normal(size=(500, 3))
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    first = ray.intersects_first(origins, dirs)
    mesh = gq.TriangleMesh(v, f)
    for i in range(0, 500, 10):
        h = gq.raycast(origins[i], dirs[i], mesh, both_sides=True)
        assert (h.face_index if h is not None else -1) == first[i]
    closest, distance, tri = gtm.ProximityQuery(Mesh()).on_surface(origins[:50])
    for i in range(50):
        d, c, t = gq.point_distance(origins[i], mesh)
        assert distance[i] == d and tri[i] == t
