"""Batched forms (N, 3) / (N, 7) and scenes: bitwise the loop of single queries, in float32 and float64."""

import numpy as np
import pytest

import geomquery as gq
from conftest import cube_mesh, icosphere

DTYPES = [np.float32, np.float64]


def random_poses(rng, n, dtype, spread=2.0):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    return np.hstack([rng.uniform(-spread, spread, (n, 3)), q]).astype(dtype)


def icosphere_and_origins(dtype, seed, n):
    """An icosphere mesh in dtype, the seeded generator, and n ray origins in [-2, 2]^3 drawn from it first."""
    v, f = icosphere(2)
    rng = np.random.default_rng(seed)
    return gq.TriangleMesh(v.astype(dtype), f), rng, rng.uniform(-2, 2, (n, 3)).astype(dtype)


@pytest.mark.parametrize("dtype", DTYPES)
def test_ray_batch_equals_single_rays(dtype):
    mesh, rng, origins = icosphere_and_origins(dtype, 5, 300)
    dirs = rng.normal(size=(300, 3))
    dirs = (dirs / np.linalg.norm(dirs, axis=1)[:, None]).astype(dtype)
    hit, dist, pos, nrm, face = gq.raycast_batch(origins, dirs, mesh)
    assert dist.dtype == dtype and pos.shape == (300, 3) and face.dtype == np.int64
    for i in range(300):
        single = gq.raycast(origins[i], dirs[i], mesh)
        assert hit[i] == (single is not None)
        if single is not None:
            assert dist[i] == dtype(single.distance) and face[i] == single.face_index
            assert np.array_equal(pos[i], single.position.astype(dtype))
        else:
            assert face[i] == -1 and np.isinf(dist[i])
    assert np.array_equal(gq.raycast_batch_faces(origins, dirs, mesh), face)
    # A strided view of the rows (every other ray) answers the same, without a copy.
    both = np.hstack([origins, dirs])
    h2 = gq.raycast_batch(both[::2, :3], both[::2, 3:], mesh)
    assert np.array_equal(h2[4], face[::2])
    single_thread = gq.raycast_batch(origins, dirs, mesh, threads=1)
    assert all(np.array_equal(a, b, equal_nan=True) for a, b in zip(single_thread, (hit, dist, pos, nrm, face)))


@pytest.mark.parametrize("dtype", DTYPES)
def test_normalizing_ray_batches_equal_numpy_normalized_rays(dtype):
    mesh, rng, origins = icosphere_and_origins(dtype, 9, 400)
    dirs = (rng.normal(size=(400, 3)) * rng.uniform(1e-3, 1e3, (400, 1))).astype(dtype)
    unit = dirs / np.linalg.norm(dirs, axis=1)[:, None]  # what the batch computes, bit for bit
    expected = gq.raycast_batch(origins, unit, mesh, both_sides=True)
    got = gq.raycast_batch(origins, dirs, mesh, both_sides=True, normalize=True)
    assert all(np.array_equal(a, b) for a, b in zip(got, expected))
    assert np.array_equal(gq.raycast_batch_faces(origins, dirs, mesh, both_sides=True, normalize=True), expected[4])
    scene = gq.Scene(dtype=dtype)
    scene.add(3, mesh)
    assert all(np.array_equal(a, b) for a, b in zip(scene.raycast_batch(origins, dirs, normalize=True),
                                                     scene.raycast_batch(origins, unit)))
    assert all(np.array_equal(a, b) for a, b in zip(scene.raycast_all_batch(origins, dirs, normalize=True),
                                                     scene.raycast_all_batch(origins, unit)))


def test_normalizing_ray_batches_reject_zero_length_directions():
    mesh = gq.TriangleMesh(*cube_mesh())
    origins = np.zeros((5, 3)) - 5
    dirs = np.tile([2.0, 0.0, 0.0], (5, 1))
    dirs[3] = 0.0
    for call in (lambda: gq.raycast_batch(origins, dirs, mesh, normalize=True),
                 lambda: gq.raycast_batch_faces(origins, dirs, mesh, normalize=True),
                 lambda: gq.raycast_batch_faces(origins, dirs, gq.Sphere(1.0), normalize=True)):
        with pytest.raises(ValueError, match="item 3.*zero-length"):
            call()
    scene = gq.Scene()
    scene.add(0, mesh)
    with pytest.raises(ValueError, match="item 3.*zero-length"):
        scene.raycast_all_batch(origins, dirs, normalize=True)
    # Without normalize, a non-unit direction is the item's error, as in the single raycast.
    with pytest.raises(ValueError, match="item 0"):
        gq.raycast_batch(origins, dirs, mesh)


@pytest.mark.parametrize("dtype", DTYPES)
def test_pose_batches_equal_single_queries(dtype):
    rng = np.random.default_rng(7)
    box = gq.Box((0.5, 0.7, 0.3), dtype=dtype)
    hull = gq.ConvexMesh(icosphere(1)[0].astype(dtype))
    p0, p1 = random_poses(rng, 200, dtype), random_poses(rng, 200, dtype)
    over = gq.overlap_batch(box, p0, hull, p1)
    dist, a, b, n = gq.distance_batch(box, p0, hull, p1)
    pen, direction, depth = gq.penetration_batch(box, p0, hull, p1)
    for i in range(200):
        assert over[i] == gq.overlap(box, p0[i], hull, p1[i])
        d = gq.distance(box, p0[i], hull, p1[i])
        assert dist[i] == dtype(d.distance) and np.array_equal(a[i], d.point0.astype(dtype))
        p = gq.penetration(box, p0[i], hull, p1[i])
        assert pen[i] == p.penetrating and depth[i] == dtype(p.depth)
    assert np.array_equal(over, dist <= 0)
    # One side may be a single pose, repeated.
    fixed = gq.overlap_batch(box, p0, hull, None)
    assert all(fixed[i] == gq.overlap(box, p0[i], hull, None) for i in range(200))


def test_point_distance_batch_equals_single():
    mesh = gq.TriangleMesh(*icosphere(1))
    pts = np.random.default_rng(1).uniform(-2, 2, (100, 3))
    dist, closest, tri = gq.point_distance_batch(pts, mesh)
    for i in range(100):
        d, c, t = gq.point_distance(pts[i], mesh)
        assert dist[i] == d and np.array_equal(closest[i], c) and tri[i] == t


def test_batch_errors_name_the_item():
    mesh = gq.TriangleMesh(*cube_mesh())
    origins = np.zeros((10, 3)) - 5
    dirs = np.tile([1.0, 0.0, 0.0], (10, 1))
    origins[6, 1] = np.nan
    with pytest.raises(ValueError, match="item 6"):
        gq.raycast_batch(origins, dirs, mesh)
    with pytest.raises(ValueError, match=r"\(N, 3\)"):
        gq.raycast_batch(origins[:, :2], dirs, mesh)
    with pytest.raises(ValueError, match="contiguous"):
        gq.raycast_batch(np.asfortranarray(origins), dirs, mesh)
    with pytest.raises(TypeError, match="mixed|dtype"):
        gq.raycast_batch(origins.astype(np.float32), dirs.astype(np.float32), mesh)
    with pytest.raises(ValueError, match="count|directions"):
        gq.raycast_batch(origins, dirs[:5], mesh)
    poses = np.tile([0, 0, 0, 0, 0, 0, 1.0], (4, 1))
    poses[2, 6] = 3.0
    with pytest.raises(ValueError, match="item 2"):
        gq.overlap_batch(gq.Sphere(1.0), poses, gq.Sphere(1.0), None)
    with pytest.raises(ValueError, match="7"):
        gq.overlap_batch(gq.Sphere(1.0), np.zeros((4, 6)), gq.Sphere(1.0), None)


@pytest.mark.parametrize("dtype", DTYPES)
def test_scene_answers_what_the_loop_answers(dtype):
    rng = np.random.default_rng(11)
    scene = gq.Scene(dtype=dtype)
    shapes = {}
    for i in range(30):
        g = [gq.Sphere(0.3, dtype=dtype), gq.Box((0.2, 0.3, 0.4), dtype=dtype), gq.Capsule(0.2, 0.3, dtype=dtype)][i % 3]
        pose = random_poses(rng, 1, np.float64, spread=3.0)[0]
        scene.add(100 + i, g, pose, mask=1 if i % 2 else 2)
        shapes[100 + i] = (g, pose)
    scene.rebuild()
    assert len(scene) == 30 and 105 in scene and scene.ids() == sorted(shapes)
    probe = gq.Sphere(1.0, dtype=dtype)
    for pose in random_poses(rng, 10, np.float64, spread=3.0):
        expected = sorted(i for i, (g, p) in shapes.items() if gq.overlap(probe, pose, g, p))
        assert scene.overlap(probe, pose) == expected
        assert scene.overlap(probe, pose, mask=1) == [i for i in expected if (i - 100) % 2]
        nearest = scene.nearest(probe, pose)
        best = min(shapes, key=lambda i: (gq.distance(probe, pose, *shapes[i]).distance, i))
        assert nearest[0] == best
    pairs = scene.overlapping_pairs()
    expected = [(a, b) for a in sorted(shapes) for b in sorted(shapes) if a < b and (a - b) % 2 == 0 and
                gq.overlap(shapes[a][0], shapes[a][1], shapes[b][0], shapes[b][1])]
    assert [tuple(p) for p in pairs.tolist()] == expected
    origins = rng.uniform(-4, 4, (50, 3)).astype(dtype)
    dirs = rng.normal(size=(50, 3))
    dirs = (dirs / np.linalg.norm(dirs, axis=1)[:, None]).astype(dtype)
    hit, ids, dist, _, _, _ = scene.raycast_batch(origins, dirs)
    for i in range(50):
        single = scene.raycast(origins[i], dirs[i])
        assert hit[i] == (single is not None)
        if single is not None:
            assert ids[i] == single[0] and dist[i] == dtype(single[1].distance)
    scene.set_pose(100, (50, 0, 0, 0, 0, 0, 1))
    assert np.allclose(scene.pose(100).position, [50, 0, 0])
    scene.remove(100)
    assert 100 not in scene
    with pytest.raises(ValueError):
        scene.remove(100)
    with pytest.raises(TypeError, match="scene"):
        scene.add(1, gq.Sphere(1.0, dtype=np.float32 if dtype == np.float64 else np.float64))


def test_scene_multi_hits_sorted_per_ray():
    scene = gq.Scene()
    scene.add(1, gq.TriangleMesh(*cube_mesh()), None)
    scene.add(2, gq.Sphere(0.5), (5, 0, 0, 0, 0, 0, 1))
    ray, ids, dist, pos, face = scene.raycast_all_batch(np.array([[-5.0, 0.1, 0.1], [0.0, 5.0, 5.0]]),
                                                        np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]))
    assert set(ray.tolist()) == {0} and ids[0] == 1 and ids[-1] == 2  # the second ray misses
    assert np.all(np.diff(dist) >= 0) and dist[0] == pytest.approx(4.0) and dist[-1] == pytest.approx(10.0 - np.sqrt(0.23))
    assert np.allclose(pos[0], [-1.0, 0.1, 0.1]) and face[-1] == -1


def test_batches_call_python_custom_shapes_from_worker_threads():
    ball = gq.CustomShape(lambda d: np.asarray(d) / np.linalg.norm(d) * 0.5, ((-0.5,) * 3, (0.5,) * 3))
    poses = random_poses(np.random.default_rng(2), 64, np.float64)
    over = gq.overlap_batch(ball, poses, gq.Sphere(0.5), None)
    expected = np.linalg.norm(poses[:, :3], axis=1) <= 1.0
    assert np.array_equal(over, expected)


@pytest.mark.parametrize("dtype", DTYPES)
def test_ray_batches_answer_the_same_with_a_kept_scratch_across_calls(dtype):
    # 70,000 rays: enough per thread (32,768) for the batch's coherent order, which is what uses the scratch.
    mesh, rng, origins = icosphere_and_origins(dtype, 11, 70000)
    dirs = rng.normal(size=(70000, 3))
    dirs = (dirs / np.linalg.norm(dirs, axis=1)[:, None]).astype(dtype)
    fresh = gq.raycast_batch(origins, dirs, mesh, both_sides=True)
    scratch = gq.BatchScratch()
    assert scratch.bytes == 0
    for threads in (1, 2, 1):
        kept = gq.raycast_batch(origins, dirs, mesh, both_sides=True, threads=threads, scratch=scratch)
        assert all(np.array_equal(a, b) for a, b in zip(kept, fresh))
        assert scratch.bytes > 0
    # A larger batch grows the kept arrays; a smaller one reuses them.
    twice = (np.vstack([origins, origins[::-1]]), np.vstack([dirs, dirs[::-1]]))
    faces = gq.raycast_batch_faces(*twice, mesh, both_sides=True, scratch=scratch)
    assert np.array_equal(faces[:70000], fresh[4]) and np.array_equal(faces[70000:], fresh[4][::-1])
    assert np.array_equal(gq.raycast_batch_faces(origins, dirs, mesh, both_sides=True, scratch=scratch), fresh[4])
    for i in range(0, 70000, 997):
        single = gq.raycast(origins[i], dirs[i], mesh, both_sides=True)
        assert fresh[4][i] == (single.face_index if single is not None else -1)
    # A bad ray fails the call naming it, with or without the scratch, and leaves the scratch usable.
    bad = origins.copy()
    bad[40000, 1] = np.nan
    for kept in (None, scratch):
        with pytest.raises(ValueError, match="item 40000"):
            gq.raycast_batch_faces(bad, dirs, mesh, both_sides=True, scratch=kept)
    assert np.array_equal(gq.raycast_batch_faces(origins, dirs, mesh, both_sides=True, scratch=scratch), fresh[4])
    scratch.release()
    assert scratch.bytes == 0


def test_a_batch_scratch_of_the_wrong_type_raises_type_error():
    mesh, rng, origins = icosphere_and_origins(np.float64, 3, 10)
    dirs = np.tile([0.0, 0.0, 1.0], (10, 1))
    for wrong in (object(), 3, "scratch", mesh):
        with pytest.raises(TypeError):
            gq.raycast_batch(origins, dirs, mesh, scratch=wrong)
        with pytest.raises(TypeError):
            gq.raycast_batch_faces(origins, dirs, mesh, scratch=wrong)
    assert gq.raycast_batch_faces(origins, dirs, mesh, scratch=None).shape == (10,)


def test_python_threads_sharing_one_batch_scratch_take_turns():
    import threading

    mesh, rng, origins = icosphere_and_origins(np.float64, 13, 70000)
    dirs = rng.normal(size=(70000, 3))
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    expected = gq.raycast_batch_faces(origins, dirs, mesh)
    scratch = gq.BatchScratch()
    results = []

    def cast():
        for _ in range(3):
            results.append(gq.raycast_batch_faces(origins, dirs, mesh, threads=1, scratch=scratch))

    workers = [threading.Thread(target=cast) for _ in range(3)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert len(results) == 9 and all(np.array_equal(r, expected) for r in results)
    assert scratch.bytes > 0
