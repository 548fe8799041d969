"""geomquery's single queries in float32 and float64 against closed forms and brute force, and its errors."""

import numpy as np
import pytest

import geomquery as gq
from conftest import brute_point_distance, brute_rays, cube_mesh, icosphere

DTYPES = [np.float32, np.float64]


def tol(dtype):
    return 1e-4 if dtype == np.float32 else 1e-9


@pytest.mark.parametrize("dtype", DTYPES)
def test_sphere_pair_queries_match_closed_forms(dtype):
    a, b = gq.Sphere(1.0, dtype=dtype), gq.Sphere(0.5, dtype=dtype)
    assert a.dtype == np.dtype(dtype)
    far = gq.Pose((3.0, 0.0, 0.0))
    d = gq.distance(a, None, b, far)
    assert d.distance == pytest.approx(1.5, abs=tol(dtype))
    assert np.allclose(d.normal, [1, 0, 0], atol=tol(dtype))
    assert np.allclose(d.point0, [1, 0, 0], atol=tol(dtype)) and np.allclose(d.point1, [2.5, 0, 0], atol=tol(dtype))
    assert not gq.overlap(a, None, b, far)
    near = (1.2, 0, 0, 0, 0, 0, 1)
    assert gq.overlap(a, None, b, near)
    p = gq.penetration(a, None, b, near)
    assert p.penetrating and p.depth == pytest.approx(0.3, abs=tol(dtype))
    assert np.allclose(p.direction, [-1, 0, 0], atol=tol(dtype))  # moves geometry0 out of geometry1


@pytest.mark.parametrize("dtype", DTYPES)
def test_every_primitive_answers_raycast_and_bounds(dtype):
    shapes = {
        "sphere": (gq.Sphere(1.0, dtype=dtype), 1.0),
        "box": (gq.Box((1.0, 2.0, 3.0), dtype=dtype), 1.0),
        "capsule": (gq.Capsule(0.5, 2.0, dtype=dtype), 2.5),  # axis along X
        "cylinder": (gq.Cylinder(0.5, 2.0, dtype=dtype), 2.0),
        "cone": (gq.Cone(0.5, 2.0, dtype=dtype), 2.0),  # base disk at -X (the ray comes from -X)
        "ellipsoid": (gq.Ellipsoid((1.5, 1.0, 1.0), dtype=dtype), 1.5),
        "convex": (gq.ConvexMesh(cube_mesh(1.0)[0].astype(dtype)), 1.0),
        "plane": (gq.Plane(dtype=dtype), 0.0),
    }
    for name, (g, front) in shapes.items():
        side = -1.0 if name == "cone" else 1.0
        hit = gq.raycast((10.0 * side, 0.0, 0.0), (-side, 0.0, 0.0), g)
        assert hit is not None, name
        assert hit.distance == pytest.approx(10.0 - front, abs=1e-4), name
        assert hit.normal[0] == pytest.approx(side, abs=1e-4), name
        assert gq.raycast((10.0, 5.0, 5.0), (1.0, 0.0, 0.0), g) is None, name
        if name != "plane":
            lo, hi = gq.bounds(g)
            assert hi[0] >= front - 1e-6 and lo[0] <= -0.5, name


@pytest.mark.parametrize("dtype", DTYPES)
def test_mesh_raycast_and_point_distance_match_brute_force(dtype):
    v, f = icosphere(1)
    mesh = gq.TriangleMesh(v.astype(dtype), f)
    assert mesh.dtype == np.dtype(dtype)
    assert mesh.cook_report["input_triangles"] == len(f) and mesh.cook_report["removed_degenerate"] == 0
    rng = np.random.default_rng(3)
    origins = rng.uniform(-2, 2, (40, 3))
    dirs = rng.normal(size=(40, 3))
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    hits = brute_rays(v, f, origins, dirs)
    for r in range(len(origins)):
        mine = [t for rr, _, t in hits if rr == r]
        h = gq.raycast(origins[r], dirs[r], mesh, both_sides=True)
        if not mine:
            assert h is None
        else:
            assert h is not None and h.distance == pytest.approx(min(mine), abs=1e-4)
            assert 0 <= h.face_index < len(f)
    for p in rng.uniform(-2, 2, (15, 3)):
        dist, closest, tri = gq.point_distance(p, mesh)
        assert dist == pytest.approx(brute_point_distance(v, f, p), abs=1e-4)
        assert np.linalg.norm(closest - p) == pytest.approx(dist, abs=1e-4)
        assert 0 <= tri < len(f)


def test_multi_hit_raycast_reports_both_sides_of_a_closed_mesh():
    mesh = gq.TriangleMesh(*cube_mesh(1.0))
    hits = gq.raycast((-5.0, 0.1, 0.2), (1.0, 0.0, 0.0), mesh, max_hits=8, both_sides=True)
    assert sorted(round(h.distance, 9) for h in hits) == [4.0, 6.0]


def test_sweep_and_mtd():
    box = gq.Box((1.0, 1.0, 1.0))
    ball = gq.Sphere(0.5)
    hit = gq.sweep((1.0, 0.0, 0.0), 10.0, ball, (-5, 0, 0, 0, 0, 0, 1), box, None)
    assert hit.distance == pytest.approx(3.5)
    assert np.allclose(hit.normal, [-1, 0, 0])
    assert gq.sweep((0.0, 1.0, 0.0), 10.0, ball, (-5, 0, 0, 0, 0, 0, 1), box, None) is None
    start = gq.sweep((1.0, 0.0, 0.0), 10.0, ball, None, box, None, mtd=True)
    assert start.initial_overlap and start.distance == pytest.approx(-1.5)


def test_mesh_queries():
    v, f = cube_mesh(1.0)
    mesh = gq.TriangleMesh(v, f)
    tri = gq.get_triangle(mesh, (1, 0, 0, 0, 0, 0, 1), 0)
    assert np.allclose(tri, v[f[0]] + [1, 0, 0])
    touching = gq.find_overlapping_triangles(gq.Sphere(0.5), (1.2, 0, 0, 0, 0, 0, 1), mesh, None)
    assert sorted(touching.tolist()) == [2, 3]  # the +x face
    pen = gq.mesh_penetration(gq.Sphere(0.5), (1.2, 0, 0, 0, 0, 0, 1), mesh, None)
    assert pen.penetrating and np.allclose(pen.direction, [1, 0, 0]) and pen.depth == pytest.approx(0.3)
    pairs = gq.mesh_triangle_pairs(mesh, None, mesh, (1.9, 0, 0, 0, 0, 0, 1))
    assert pairs.shape[1] == 2 and len(pairs) > 0
    assert len(gq.mesh_triangle_pairs(mesh, None, mesh, (5, 0, 0, 0, 0, 0, 1))) == 0
    hit = gq.sweep_triangles((0.0, 0.0, -1.0), 10.0, gq.Sphere(0.5), (0, 0, 5, 0, 0, 0, 1),
                             np.array([[[-1, -1, 0], [1, -1, 0], [0, 1, 0]]], dtype=np.float64))
    assert hit.distance == pytest.approx(4.5) and hit.face_index == 0
    contacts = gq.triangle_contacts(gq.Box((0.5, 0.5, 0.5)), (0, 0, 0.4, 0, 0, 0, 1),
                                    np.array([[-2, -2, 0], [2, -2, 0], [0, 2, 0]], dtype=np.float64), 7)
    assert 1 <= len(contacts) <= 4
    for c in contacts:
        assert c.triangle_index == 7 and c.separation == pytest.approx(-0.1) and np.allclose(c.normal, [0, 0, 1])


def test_heightfield_raycast():
    hf = gq.HeightField(np.full((5, 5), 2.0), row_scale=1.0, column_scale=1.0)
    hit = gq.raycast((2.0, 10.0, 2.0), (0.0, -1.0, 0.0), hf)
    assert hit.distance == pytest.approx(8.0) and np.allclose(hit.normal, [0, 1, 0])


def test_custom_shape_from_python_callables():
    calls = []

    def support(d):
        calls.append(d)
        d = np.asarray(d)
        return d / np.linalg.norm(d) * 0.75

    ball = gq.CustomShape(support, ((-0.75, -0.75, -0.75), (0.75, 0.75, 0.75)))
    d = gq.distance(ball, None, gq.Sphere(0.25), (2.0, 0, 0, 0, 0, 0, 1))
    assert d.distance == pytest.approx(1.0, abs=1e-5) and calls
    assert gq.overlap(ball, None, gq.Sphere(0.25), (0.9, 0, 0, 0, 0, 0, 1))

    def broken(d):
        raise KeyError("boom")

    bad = gq.CustomShape(broken, ((-1, -1, -1), (1, 1, 1)))
    with pytest.raises(RuntimeError, match="boom"):
        gq.distance(bad, None, gq.Sphere(0.25), (2.0, 0, 0, 0, 0, 0, 1))


def test_pose_order_and_conversions():
    s = np.sqrt(0.5)
    pose = gq.Pose((1.0, 2.0, 3.0), (0.0, 0.0, s, s))  # 90 degrees about Z
    assert np.allclose(pose.to_array(), [1, 2, 3, 0, 0, s, s])
    assert np.allclose(pose.transform_point((1, 0, 0)), [1, 3, 3])
    assert np.allclose(gq.Pose.from_matrix(pose.matrix()).to_array(), pose.to_array())
    assert np.allclose((pose * pose.inverse()).to_array(), [0, 0, 0, 0, 0, 0, 1], atol=1e-12)
    box = gq.Box((2.0, 0.5, 0.5))  # long along X, rotated onto Y by the pose
    assert gq.overlap(box, pose, gq.Sphere(0.1), (1.0, 3.9, 3.0, 0, 0, 0, 1))


def test_errors_raise_with_messages():
    with pytest.raises(ValueError, match="radius"):
        gq.Sphere(-1.0)
    with pytest.raises(ValueError, match="unit"):
        gq.raycast((0, 0, 0), (2.0, 0, 0), gq.Sphere(1.0))
    with pytest.raises(ValueError, match="finite|NaN"):
        gq.raycast((np.nan, 0, 0), (1.0, 0, 0), gq.Sphere(1.0))
    with pytest.raises(ValueError, match="quaternion|unit"):
        gq.overlap(gq.Sphere(1.0), (0, 0, 0, 0, 0, 0, 2), gq.Sphere(1.0), None)
    with pytest.raises(ValueError, match="7 numbers"):
        gq.overlap(gq.Sphere(1.0), (0, 0, 0), gq.Sphere(1.0), None)
    with pytest.raises(TypeError, match="mixing"):
        gq.overlap(gq.Sphere(1.0, dtype=np.float32), None, gq.Sphere(1.0), None)
    with pytest.raises(TypeError, match="dtype"):
        gq.Sphere(1.0, dtype=np.int32)
    with pytest.raises(gq.UnsupportedError, match="penetration"):
        gq.penetration(gq.Plane(), None, gq.TriangleMesh(*cube_mesh()), None)
    assert issubclass(gq.UnsupportedError, NotImplementedError)
    v, f = cube_mesh()
    with pytest.raises(ValueError, match="shape"):
        gq.TriangleMesh(v[:, :2], f)
    with pytest.raises(ValueError):
        gq.TriangleMesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int64))
    with pytest.raises(ValueError, match="out of range|index"):
        gq.TriangleMesh(v, f + 100)
    with pytest.raises(TypeError, match="integer"):
        gq.TriangleMesh(v, f.astype(np.float64))
    with pytest.raises(TypeError, match="dtype"):
        gq.TriangleMesh(v.astype(np.complex128), f)
    with pytest.raises(ValueError, match="degenerate|coplanar|DegenerateMesh|points"):
        gq.ConvexMesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=np.float64))
    with pytest.raises(ValueError, match="NaN|finite"):
        gq.TriangleMesh(np.where(np.arange(24).reshape(8, 3) == 5, np.nan, v), f)


def test_overlap_fast_and_general_paths_agree():
    s, b = gq.Sphere(1.0), gq.Box((1.0, 1.0, 1.0))
    for x in (1.5, 2.5):
        pose = gq.Pose((x, 0.0, 0.0))
        answers = {
            gq.overlap(s, pose, b, None),
            gq.overlap(s, (x, 0, 0, 0, 0, 0, 1), b, gq.Pose()),
            gq.overlap(geometry0=s, pose0=pose, geometry1=b, pose1=None),
            gq.overlap(s, np.array([x, 0, 0, 0, 0, 0, 1.0]), b, None),
        }
        assert answers == {x < 2.0}
    with pytest.raises(ValueError, match="pose1.*unit"):
        gq.overlap(s, None, b, gq.Pose(None, (0.0, 0.0, 0.0, 2.0)))
    with pytest.raises(TypeError):
        gq.overlap(s, None, "box", None)
    with pytest.raises(TypeError):
        gq.overlap(s, None, b)
