"""geomquery.fcl: python-fcl's README examples replayed through the switch, with python-fcl's conventions."""

import numpy as np
import pytest

import geomquery.fcl as fcl


def test_readme_geometries_and_transforms():
    v1, v2, v3 = np.array([1.0, 2.0, 3.0]), np.array([2.0, 1.0, 3.0]), np.array([3.0, 2.0, 1.0])
    x, y, z = 1, 2, 3
    rad, lz = 1.0, 3.0
    n, d = np.array([1.0, 0.0, 0.0]), 5.0
    shapes = [fcl.TriangleP(v1, v2, v3), fcl.Box(x, y, z), fcl.Sphere(rad), fcl.Ellipsoid(x, y, z),
              fcl.Capsule(rad, lz), fcl.Cone(rad, lz), fcl.Cylinder(rad, lz), fcl.Halfspace(n, d), fcl.Plane(n, d)]
    verts = np.array([[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]])
    tris = np.array([[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 2, 3]])
    m = fcl.BVHModel()
    m.beginModel(len(verts), len(tris))
    m.addSubModel(verts, tris)
    m.endModel()
    shapes.append(m)
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    T = np.array([1.0, 2.0, 3.0])
    q = np.array([0.707, 0.0, 0.0, 0.707])
    for tf in [fcl.Transform(), fcl.Transform(q), fcl.Transform(R), fcl.Transform(T), fcl.Transform(q, T),
               fcl.Transform(R, T)]:
        fcl.Transform(tf)
    assert np.allclose(fcl.Transform(q, T).getRotation(), R, atol=1e-3)
    assert np.allclose(fcl.Transform(R, T).getQuatRotation(), q / np.linalg.norm(q))
    obj = fcl.CollisionObject(fcl.Box(x, y, z), fcl.Transform(R, T))
    obj.setTransform(fcl.Transform(R, T))
    obj.setRotation(np.eye(3))
    obj.setTranslation(np.array([0.5, 0.0, 0.0]))
    obj.setQuatRotation(np.array([1.0, 0.0, 0.0, 0.0]))
    assert np.allclose(obj.getTranslation(), [0.5, 0, 0]) and np.allclose(obj.getRotation(), np.eye(3))
    # Every shape collides with a big sphere around it (a mesh surface inside a solid sphere does not touch it).
    big = fcl.CollisionObject(fcl.Sphere(20.0))
    for s in shapes:
        if s is m:
            continue
        assert fcl.collide(fcl.CollisionObject(s), big) >= 1, type(s).__name__


def test_readme_collision_and_distance():
    o1 = fcl.CollisionObject(fcl.Box(1, 2, 3), fcl.Transform())
    o2 = fcl.CollisionObject(fcl.Cone(1, 3), fcl.Transform())
    request, result = fcl.CollisionRequest(), fcl.CollisionResult()
    ret = fcl.collide(o1, o2, request, result)
    assert ret == 1 and result.is_collision and len(result.contacts) == 1
    assert result.contacts[0].o1 is o1.geom and result.contacts[0].o2 is o2.geom

    o2.setTranslation(np.array([3.0, 0.0, 0.0]))
    request, result = fcl.DistanceRequest(), fcl.DistanceResult()
    ret = fcl.distance(o1, o2, request, result)
    assert ret == pytest.approx(1.5) and result.min_distance == pytest.approx(1.5)  # box face x=0.5, cone r=1
    assert np.allclose(result.nearest_points[0][0], 0.5) and np.allclose(result.nearest_points[1][0], 2.0)
    assert result.o1 is o1.geom and result.o2 is o2.geom


def test_contacts_follow_fcl_conventions():
    a = fcl.CollisionObject(fcl.Sphere(1.0))
    b = fcl.CollisionObject(fcl.Sphere(1.0), fcl.Transform(np.array([0.0, 0.0, 1.5])))
    result = fcl.CollisionResult()
    fcl.collide(a, b, fcl.CollisionRequest(num_max_contacts=10, enable_contact=True), result)
    c = result.contacts[0]
    assert np.allclose(c.normal, [0, 0, 1])  # from o1 towards o2
    assert c.penetration_depth == pytest.approx(0.5) and np.allclose(c.pos, [0, 0, 0.75])
    assert c.b1 == -1 and c.b2 == -1
    # Capsule and cylinder lie along Z: a sphere above the capsule's end touches it, one beside it does not.
    cap = fcl.CollisionObject(fcl.Capsule(0.5, 2.0))
    assert fcl.collide(cap, fcl.CollisionObject(fcl.Sphere(0.2), fcl.Transform(np.array([0.0, 0.0, 1.6])))) == 1
    assert fcl.collide(cap, fcl.CollisionObject(fcl.Sphere(0.2), fcl.Transform(np.array([1.6, 0.0, 0.0])))) == 0
    # Halfspace {x : n.x <= d} is solid; Plane {x : n.x = d} is a surface.
    hs = fcl.CollisionObject(fcl.Halfspace(np.array([0.0, 0.0, 1.0]), 0.0))
    plane = fcl.CollisionObject(fcl.Plane(np.array([0.0, 0.0, 1.0]), 0.0))
    deep = fcl.CollisionObject(fcl.Sphere(0.5), fcl.Transform(np.array([0.0, 0.0, -3.0])))
    assert fcl.collide(hs, deep) == 1 and fcl.collide(plane, deep) == 0
    crossing = fcl.CollisionObject(fcl.Sphere(0.5), fcl.Transform(np.array([0.0, 0.0, 0.2])))
    assert fcl.collide(plane, crossing) == 1
    assert fcl.distance(plane, deep) == pytest.approx(2.5)


def test_colliding_distance_is_minus_one_unless_signed_distance_is_asked():
    a = fcl.CollisionObject(fcl.Sphere(1.0))
    b = fcl.CollisionObject(fcl.Sphere(1.0), fcl.Transform(np.array([0.0, 0.0, 1.5])))
    result = fcl.DistanceResult()
    assert fcl.distance(a, b, fcl.DistanceRequest(enable_nearest_points=True), result) == -1.0
    assert result.min_distance == -1.0 and np.allclose(result.nearest_points, 0.0)
    signed = fcl.DistanceRequest(True, True)  # python-fcl's order: enable_nearest_points, enable_signed_distance
    result = fcl.DistanceResult()
    assert fcl.distance(a, b, signed, result) == pytest.approx(-0.5)
    assert np.allclose(result.nearest_points[0], [0, 0, 1.0]) and np.allclose(result.nearest_points[1], [0, 0, 0.5])


def test_mesh_contacts_carry_triangle_indices():
    verts = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]])
    m = fcl.BVHModel()
    m.beginModel(3, 1)
    m.addSubModel(verts, np.array([[0, 1, 2]]))
    m.endModel()
    mesh = fcl.CollisionObject(m)
    ball = fcl.CollisionObject(fcl.Sphere(0.5), fcl.Transform(np.array([0.0, 0.0, 0.3])))
    result = fcl.CollisionResult()
    assert fcl.collide(mesh, ball, fcl.CollisionRequest(enable_contact=True), result) == 1
    assert result.contacts[0].b1 == 0 and result.contacts[0].b2 == -1 and result.contacts[0].o1 is m
    other = fcl.CollisionObject(m, fcl.Transform(np.array([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]])))
    result = fcl.CollisionResult()
    assert fcl.collide(mesh, other, fcl.CollisionRequest(num_max_contacts=5), result) == 1
    assert (result.contacts[0].b1, result.contacts[0].b2) == (0, 0)


def _box_model(half):
    """A closed, outward-wound box mesh of half extents `half` as a BVHModel."""
    signs = np.array([[(1 if i & 1 else -1), (1 if i & 2 else -1), (1 if i & 4 else -1)] for i in range(8)], float)
    tris = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                     [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    m = fcl.BVHModel()
    m.beginModel(8, 12)
    m.addSubModel(signs * np.asarray(half, float), tris)
    m.endModel()
    return m


def test_mesh_mesh_contacts_carry_the_overlap_depth():
    # Box A (half 1) at the origin, box B (half 1, 0.5, 0.5) at x = 1.8: B enters A by 0.2 through A's +x face, and
    # every crossing triangle pair is pushed out through that face (B's side faces lie 0.5 inside A's).
    a, b = _box_model([1.0, 1.0, 1.0]), _box_model([1.0, 0.5, 0.5])
    oa = fcl.CollisionObject(a)
    ob = fcl.CollisionObject(b, fcl.Transform(np.array([1.8, 0.0, 0.0])))
    result = fcl.CollisionResult()
    n = fcl.collide(oa, ob, fcl.CollisionRequest(num_max_contacts=100, enable_contact=True), result)
    assert n == len(result.contacts) > 0
    for c in result.contacts:
        assert c.penetration_depth == pytest.approx(0.2, abs=1e-12)
        assert np.allclose(c.normal, [1.0, 0.0, 0.0], atol=1e-12)  # python-fcl's: from o1 towards o2
        assert c.pos[0] == pytest.approx(0.9, abs=1e-12)
        assert 0 <= c.b1 < 12 and 0 <= c.b2 < 12 and c.o1 is a and c.o2 is b
    # Swapped objects: the same depth, the normal turned.
    result = fcl.CollisionResult()
    assert fcl.collide(ob, oa, fcl.CollisionRequest(num_max_contacts=3, enable_contact=True), result) == 3
    for c in result.contacts:
        assert c.penetration_depth == pytest.approx(0.2, abs=1e-12)
        assert np.allclose(c.normal, [-1.0, 0.0, 0.0], atol=1e-12)


def test_readme_broadphase():
    box, sphere = fcl.Box(1, 2, 3), fcl.Sphere(4)
    cone, cyl = fcl.Cone(5, 6), fcl.Cylinder(2, 8)
    verts = np.array([[1.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]])
    mesh = fcl.BVHModel()
    mesh.beginModel(4, 4)
    mesh.addSubModel(verts, np.array([[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 2, 3]]))
    mesh.endModel()
    objs1 = [fcl.CollisionObject(box), fcl.CollisionObject(sphere)]
    objs2 = [fcl.CollisionObject(cone, fcl.Transform(np.array([20.0, 0, 0]))), fcl.CollisionObject(mesh)]
    manager1, manager2 = fcl.DynamicAABBTreeCollisionManager(), fcl.DynamicAABBTreeCollisionManager()
    manager1.registerObjects(objs1)
    manager2.registerObjects(objs2)
    manager1.setup()
    manager2.setup()

    cdata = fcl.CollisionData()
    manager1.collide(cdata, fcl.defaultCollisionCallback)
    assert cdata.result.is_collision

    ddata = fcl.DistanceData()
    manager1.distance(ddata, fcl.defaultDistanceCallback)
    assert ddata.result.min_distance < 0

    req = fcl.CollisionRequest(num_max_contacts=100, enable_contact=True)
    rdata = fcl.CollisionData(request=req)
    manager1.collide(fcl.CollisionObject(mesh), rdata, fcl.defaultCollisionCallback)
    assert rdata.result.is_collision
    assert {id(c.o2) for c in rdata.result.contacts} == {id(mesh)}
    assert {id(c.o1) for c in rdata.result.contacts} <= {id(box), id(sphere)}

    rdata = fcl.CollisionData(request=req)
    manager1.collide(manager2, rdata, fcl.defaultCollisionCallback)
    names = {id(box): "box", id(sphere): "sphere", id(cone): "cone", id(mesh): "mesh"}
    pairs = {(names[id(c.o1)], names[id(c.o2)]) for c in rdata.result.contacts}
    assert pairs == {("sphere", "mesh")}  # the cone is far away; the box (|x| <= 0.5) misses the mesh (x >= 1)

    far = fcl.DynamicAABBTreeCollisionManager()
    far.registerObjects([fcl.CollisionObject(fcl.Sphere(1.0), fcl.Transform(np.array([x, 0.0, 0.0])))
                         for x in (0.0, 5.0, 12.0)])
    far.setup()
    ddata = fcl.DistanceData()
    far.distance(ddata, fcl.defaultDistanceCallback)
    assert ddata.result.min_distance == pytest.approx(3.0)
    far.update()
    assert far.size() == 3 and not far.empty()


def test_continuous_collide_translation_is_the_exact_first_contact():
    box = fcl.CollisionObject(fcl.Box(1.0, 1.0, 1.0))
    ball = fcl.CollisionObject(fcl.Sphere(0.5), fcl.Transform(np.array([-3.0, 0.0, 0.0])))
    result = fcl.ContinuousCollisionResult()
    toc = fcl.continuousCollide(ball, fcl.Transform(np.array([3.0, 0.0, 0.0])), box, fcl.Transform(), None, result)
    assert toc == pytest.approx(1.0 / 3.0, abs=1e-9)  # the centre reaches x = -1 after 2 of 6 units
    assert result.is_collide and result.time_of_contact == pytest.approx(1.0 / 3.0, abs=1e-9)
    # Both moving: only the relative motion counts (the box comes 1 unit towards the ball: contact at 2 of 7).
    toc = fcl.continuousCollide(ball, fcl.Transform(np.array([3.0, 0.0, 0.0])), box,
                                fcl.Transform(np.array([-1.0, 0.0, 0.0])))
    assert toc == pytest.approx(2.0 / 7.0, abs=1e-9)
    # Passing beside the box: no contact, time 1.
    beside = fcl.CollisionObject(fcl.Sphere(0.5), fcl.Transform(np.array([-3.0, 1.5, 0.0])))
    result = fcl.ContinuousCollisionResult()
    assert fcl.continuousCollide(beside, fcl.Transform(np.array([3.0, 1.5, 0.0])), box, fcl.Transform(),
                                 None, result) == 1.0
    assert not result.is_collide


def test_continuous_collide_moves_a_mesh_by_sweeping_the_other_way():
    m = fcl.BVHModel()
    m.beginModel(3, 1)
    m.addSubModel(np.array([[-5.0, -5.0, 0.0], [5.0, -5.0, 0.0], [0.0, 5.0, 0.0]]), np.array([[0, 1, 2]]))
    m.endModel()
    mesh = fcl.CollisionObject(m, fcl.Transform(np.array([0.0, 0.0, -2.0])))
    ball = fcl.CollisionObject(fcl.Sphere(0.5))
    toc = fcl.continuousCollide(mesh, fcl.Transform(np.array([0.0, 0.0, 2.0])), ball, fcl.Transform())
    assert toc == pytest.approx(1.5 / 4.0, abs=1e-9)


def test_continuous_collide_with_rotation_advances_to_within_toc_err():
    # A 2 x 0.2 x 0.2 bar turning a quarter turn about z towards a ball of radius 0.1 at (0, 0.8, 0): its side
    # touches the ball when 0.8 cos(phi) = 0.2, phi = t * pi / 2.
    bar = fcl.CollisionObject(fcl.Box(2.0, 0.2, 0.2))
    ball = fcl.CollisionObject(fcl.Sphere(0.1), fcl.Transform(np.array([0.0, 0.8, 0.0])))
    quarter = np.array([np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)])  # (w, x, y, z)
    request = fcl.ContinuousCollisionRequest(ccd_motion_type=fcl.CCDMotionType.CCDM_LINEAR)
    toc = fcl.continuousCollide(bar, fcl.Transform(quarter, np.zeros(3)), ball,
                                fcl.Transform(np.array([0.0, 0.8, 0.0])), request)
    assert toc == pytest.approx(np.arccos(0.25) / (np.pi / 2), abs=1e-3)
    with pytest.raises(NotImplementedError):
        fcl.continuousCollide(bar, fcl.Transform(quarter, np.zeros(3)), ball, fcl.Transform(),
                              fcl.ContinuousCollisionRequest(ccd_motion_type=fcl.CCDMotionType.CCDM_SCREW))
