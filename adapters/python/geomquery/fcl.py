"""python-fcl's API on gq: existing python-fcl code runs unchanged after ``import geomquery.fcl as fcl``.

Shapes keep FCL's conventions (box side lengths; capsule, cylinder and cone along local Z with ``lz`` the length of
the axis; ``Halfspace(n, d)`` the solid {x : n.x <= d}; ``Plane(n, d)`` the surface {x : n.x = d}) and are converted
once to gq's (half extents, axis along X, plane x = 0). Quaternions are (w, x, y, z) as in python-fcl.

Results follow python-fcl: ``collide`` returns the number of contacts and appends them to the result (contacts'
``o1``/``o2`` are the very geometry objects given to the collision objects; ``b1``/``b2`` are triangle indices of
meshes, -1 otherwise; ``normal`` points from o1 to o2); ``distance`` returns the pair's distance and keeps the
smallest in the result. A colliding pair's distance is -1 with both nearest points at the origin, as FCL's, unless
``DistanceRequest(enable_signed_distance=True)`` asks for gq's exact signed distance (minus the penetration depth).
"""

import sys

import numpy as np

from . import _geomquery as _gq

__all__ = [
    "TriangleP", "Box", "Sphere", "Ellipsoid", "Capsule", "Cone", "Cylinder", "Halfspace", "Plane", "Convex",
    "BVHModel", "Transform", "CollisionObject", "CollisionRequest", "CollisionResult", "Contact", "DistanceRequest",
    "DistanceResult", "CollisionData", "DistanceData", "collide", "distance", "DynamicAABBTreeCollisionManager",
    "defaultCollisionCallback", "defaultDistanceCallback", "GJKSolverType", "OBJECT_TYPE", "NODE_TYPE",
    "CCDMotionType", "CCDSolverType", "ContinuousCollisionRequest", "ContinuousCollisionResult", "continuousCollide",
]


class GJKSolverType:
    GST_LIBCCD = 0
    GST_INDEP = 1


class CCDMotionType:
    CCDM_TRANS = 0
    CCDM_LINEAR = 1
    CCDM_SCREW = 2
    CCDM_SPLINE = 3


class CCDSolverType:
    CCDC_NAIVE = 0
    CCDC_CONSERVATIVE_ADVANCEMENT = 1
    CCDC_RAY_SHOOTING = 2
    CCDC_POLYNOMIAL_SOLVER = 3


class OBJECT_TYPE:
    OT_UNKNOWN, OT_BVH, OT_GEOM, OT_OCTREE, OT_COUNT = range(5)


class NODE_TYPE:
    (BV_UNKNOWN, BV_AABB, BV_OBB, BV_RSS, BV_kIOS, BV_OBBRSS, BV_KDOP16, BV_KDOP18, BV_KDOP24, GEOM_BOX, GEOM_SPHERE,
     GEOM_ELLIPSOID, GEOM_CAPSULE, GEOM_CONE, GEOM_CYLINDER, GEOM_CONVEX, GEOM_PLANE, GEOM_HALFSPACE, GEOM_TRIANGLE,
     GEOM_OCTREE, NODE_COUNT) = range(21)


def _vec(v, n=3, what="vector"):
    a = np.asarray(v, dtype=np.float64).reshape(-1)
    if a.shape != (n,):
        raise ValueError("%s: expected %d numbers" % (what, n))
    return a


def _quat_wxyz_to_matrix(q):
    q = _vec(q, 4, "quaternion")
    norm = np.linalg.norm(q)
    if not np.isfinite(norm) or norm == 0:
        raise ValueError("quaternion: expected a finite non-zero quaternion (w, x, y, z)")
    w, x, y, z = q / norm
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def _matrix_to_quat_wxyz(r):
    tr = r[0, 0] + r[1, 1] + r[2, 2]
    if tr > 0:
        s = np.sqrt(tr + 1.0) * 2
        q = [0.25 * s, (r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s]
    elif r[0, 0] > r[1, 1] and r[0, 0] > r[2, 2]:
        s = np.sqrt(1.0 + r[0, 0] - r[1, 1] - r[2, 2]) * 2
        q = [(r[2, 1] - r[1, 2]) / s, 0.25 * s, (r[0, 1] + r[1, 0]) / s, (r[0, 2] + r[2, 0]) / s]
    elif r[1, 1] > r[2, 2]:
        s = np.sqrt(1.0 + r[1, 1] - r[0, 0] - r[2, 2]) * 2
        q = [(r[0, 2] - r[2, 0]) / s, (r[0, 1] + r[1, 0]) / s, 0.25 * s, (r[1, 2] + r[2, 1]) / s]
    else:
        s = np.sqrt(1.0 + r[2, 2] - r[0, 0] - r[1, 1]) * 2
        q = [(r[1, 0] - r[0, 1]) / s, (r[0, 2] + r[2, 0]) / s, (r[1, 2] + r[2, 1]) / s, 0.25 * s]
    q = np.array(q)
    return q / np.linalg.norm(q)


def _pose(r, t):
    w, x, y, z = _matrix_to_quat_wxyz(r)
    return _gq.Pose(t, (x, y, z, w))


# gq's axis (X) onto FCL's (Z): a quarter turn about Y.
_X_TO_Z = _gq.Pose((0.0, 0.0, 0.0), (0.0, -np.sqrt(0.5), 0.0, np.sqrt(0.5)))


def _x_onto(n):
    """A Pose rotating +X onto the unit vector n."""
    x = np.array([1.0, 0.0, 0.0])
    c = float(np.dot(x, n))
    axis = np.cross(x, n)
    s = float(np.linalg.norm(axis))
    if s < 1e-12:
        return _gq.Pose(None, (0.0, 0.0, 0.0, 1.0) if c > 0 else (0.0, 0.0, 1.0, 0.0))
    angle = np.arctan2(s, c)
    axis = axis / s
    return _gq.Pose(None, tuple(axis * np.sin(angle / 2)) + (float(np.cos(angle / 2)),))


class CollisionGeometry:
    """Base of the shapes: `_parts` are (gq geometry, pose in the shape's frame)."""

    _parts = ()
    _is_mesh = False
    _surface = False  # FCL's Plane: a surface, colliding when an object reaches both sides

    def getObjectType(self):
        return OBJECT_TYPE.OT_BVH if self._is_mesh else OBJECT_TYPE.OT_GEOM

    def computeLocalAABB(self):
        pass


class TriangleP(CollisionGeometry):
    def __init__(self, a, b, c):
        self.a, self.b, self.c = _vec(a), _vec(b), _vec(c)
        self._parts = ((_gq.TriangleMesh(np.array([self.a, self.b, self.c]), np.array([[0, 1, 2]]),
                                         double_sided=True), None),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_TRIANGLE


class Box(CollisionGeometry):
    def __init__(self, x, y, z):
        self.side = np.array([x, y, z], dtype=np.float64)
        self._parts = ((_gq.Box(self.side * 0.5), None),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_BOX


class Sphere(CollisionGeometry):
    def __init__(self, radius):
        self.radius = float(radius)
        self._parts = ((_gq.Sphere(self.radius), None),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_SPHERE


class Ellipsoid(CollisionGeometry):
    def __init__(self, a, b, c):
        self.radii = np.array([a, b, c], dtype=np.float64)
        self._parts = ((_gq.Ellipsoid(self.radii), None),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_ELLIPSOID


class Capsule(CollisionGeometry):
    def __init__(self, radius, lz):
        self.radius, self.lz = float(radius), float(lz)
        self._parts = ((_gq.Capsule(self.radius, self.lz * 0.5), _X_TO_Z),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_CAPSULE


class Cylinder(CollisionGeometry):
    def __init__(self, radius, lz):
        self.radius, self.lz = float(radius), float(lz)
        self._parts = ((_gq.Cylinder(self.radius, self.lz * 0.5), _X_TO_Z),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_CYLINDER


class Cone(CollisionGeometry):
    """Base disk at z = -lz/2, apex at z = +lz/2."""

    def __init__(self, radius, lz):
        self.radius, self.lz = float(radius), float(lz)
        self._parts = ((_gq.Cone(self.radius, self.lz * 0.5), _X_TO_Z),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_CONE


def _unit_plane(n, d):
    n = _vec(n, what="n")
    length = float(np.linalg.norm(n))
    if not np.isfinite(length) or length == 0:
        raise ValueError("n: expected a finite non-zero normal")
    return n / length, float(d) / length


class Halfspace(CollisionGeometry):
    """The solid {x : n.x <= d}."""

    def __init__(self, n, d):
        self.n, self.d = _unit_plane(n, d)
        frame = _x_onto(self.n)
        self._parts = ((_gq.Plane(), _gq.Pose(tuple(self.n * self.d), tuple(frame.quaternion))),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_HALFSPACE


class Plane(CollisionGeometry):
    """The surface {x : n.x = d}: an object collides with it when it reaches both sides."""

    _surface = True

    def __init__(self, n, d):
        self.n, self.d = _unit_plane(n, d)
        point = tuple(self.n * self.d)
        self._parts = (
            (_gq.Plane(), _gq.Pose(point, tuple(_x_onto(self.n).quaternion))),
            (_gq.Plane(), _gq.Pose(point, tuple(_x_onto(-self.n).quaternion))),
        )

    def getNodeType(self):
        return NODE_TYPE.GEOM_PLANE


class Convex(CollisionGeometry):
    """A convex polytope from its vertices and faces (num_faces, then [count, i0, i1, ...] per face): gq uses the
    hull of the vertices."""

    def __init__(self, vertices, num_faces, faces):
        self.vertices = np.ascontiguousarray(vertices, dtype=np.float64)
        self.num_faces = int(num_faces)
        self.faces = np.asarray(faces)
        self._parts = ((_gq.ConvexMesh(self.vertices), None),)

    def getNodeType(self):
        return NODE_TYPE.GEOM_CONVEX


class BVHModel(CollisionGeometry):
    """A triangle mesh: beginModel, addSubModel(verts, triangles) / addTriangle / addVertex, endModel."""

    _is_mesh = True

    def __init__(self):
        self._vertices = []
        self._triangles = []
        self._building = False
        self.num_tries_ = 0
        self.num_vertices_ = 0

    def getNodeType(self):
        return NODE_TYPE.BV_OBBRSS

    def beginModel(self, num_tris_=0, num_vertices_=0):
        self._vertices, self._triangles, self._building = [], [], True
        return 0

    def _offset(self):
        return sum(len(v) for v in self._vertices)

    def addVertex(self, x, y, z):
        self._vertices.append(np.array([[x, y, z]], dtype=np.float64))
        return 0

    def addTriangle(self, v1, v2, v3):
        base = self._offset()
        self._vertices.append(np.array([v1, v2, v3], dtype=np.float64))
        self._triangles.append(np.array([[base, base + 1, base + 2]], dtype=np.int64))
        return 0

    def addSubModel(self, verts, triangles=None):
        verts = np.asarray(verts, dtype=np.float64).reshape(-1, 3)
        base = self._offset()
        self._vertices.append(verts)
        if triangles is not None:
            self._triangles.append(np.asarray(triangles, dtype=np.int64).reshape(-1, 3) + base)
        return 0

    def endModel(self):
        if not self._vertices or not self._triangles:
            raise ValueError("BVHModel.endModel: the model has no triangles")
        vertices = np.concatenate(self._vertices)
        triangles = np.concatenate(self._triangles)
        self.num_vertices_, self.num_tries_ = len(vertices), len(triangles)
        self._parts = ((_gq.TriangleMesh(vertices, triangles), None),)
        self._building = False
        return 0


class Transform:
    """Rotation (3x3 matrix or quaternion (w, x, y, z)) and translation; Transform(), (q), (R), (T), (q, T), (R, T),
    (Transform)."""

    def __init__(self, *args):
        self._r = np.eye(3)
        self._t = np.zeros(3)
        if len(args) == 1 and isinstance(args[0], Transform):
            self._r, self._t = args[0]._r.copy(), args[0]._t.copy()
        elif len(args) == 1:
            a = np.asarray(args[0], dtype=np.float64)
            if a.shape == (3, 3):
                self._r = a.copy()
            elif a.shape == (4,):
                self._r = _quat_wxyz_to_matrix(a)
            elif a.shape == (3,):
                self._t = a.copy()
            else:
                raise ValueError("Transform: expected a rotation (3x3 or quaternion) or a translation (3)")
        elif len(args) == 2:
            a = np.asarray(args[0], dtype=np.float64)
            self._r = a.copy() if a.shape == (3, 3) else _quat_wxyz_to_matrix(a)
            self._t = _vec(args[1], what="translation").copy()
        elif args:
            raise TypeError("Transform: expected at most 2 arguments")
        self._pose = None

    def getRotation(self):
        return self._r.copy()

    def getTranslation(self):
        return self._t.copy()

    def getQuatRotation(self):
        return _matrix_to_quat_wxyz(self._r)

    def setRotation(self, R):
        self._r = np.asarray(R, dtype=np.float64).reshape(3, 3).copy()
        self._pose = None

    def setTranslation(self, T):
        self._t = _vec(T, what="translation").copy()
        self._pose = None

    def setQuatRotation(self, q):
        self._r = _quat_wxyz_to_matrix(q)
        self._pose = None

    def isIdentity(self):
        return bool(np.array_equal(self._r, np.eye(3)) and not self._t.any())

    def setIdentity(self):
        self._r, self._t, self._pose = np.eye(3), np.zeros(3), None

    def inverse(self):
        return Transform(self._r.T, -self._r.T @ self._t)

    def transform(self, v):
        return self._r @ _vec(v) + self._t

    def _gq_pose(self):
        if self._pose is None:
            self._pose = _pose(self._r, self._t)
        return self._pose


class CollisionObject:
    def __init__(self, geom=None, tf=None, _no_instance=False):
        if geom is None:
            raise ValueError("CollisionObject: expected a geometry")
        self.geom = geom
        self._tf = Transform(tf) if tf is not None else Transform()
        self._placed = None

    def getObjectType(self):
        return self.geom.getObjectType()

    def getNodeType(self):
        return self.geom.getNodeType()

    def getTranslation(self):
        return self._tf.getTranslation()

    def setTranslation(self, T):
        self._tf.setTranslation(T)
        self._placed = None

    def getRotation(self):
        return self._tf.getRotation()

    def setRotation(self, R):
        self._tf.setRotation(R)
        self._placed = None

    def getQuatRotation(self):
        return self._tf.getQuatRotation()

    def setQuatRotation(self, q):
        self._tf.setQuatRotation(q)
        self._placed = None

    def getTransform(self):
        return Transform(self._tf)

    def setTransform(self, tf):
        self._tf = Transform(tf)
        self._placed = None

    def isOccupied(self):
        return True

    def isFree(self):
        return False

    def isUncertain(self):
        return False

    def computeAABB(self):
        self._placed = None

    def _parts(self):
        """[(gq geometry, world Pose)], cached until the transform changes."""
        if self._placed is None:
            if not self.geom._parts:
                raise ValueError("CollisionObject: the geometry is empty (a BVHModel needs endModel())")
            world = self._tf._gq_pose()
            self._placed = [(g, world if local is None else world * local) for g, local in self.geom._parts]
        return self._placed

    def _aabb(self):
        lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
        for g, pose in self._parts():
            a, b = _gq.bounds(g, pose)
            lo, hi = np.minimum(lo, a), np.maximum(hi, b)
        return lo, hi


class Contact:
    def __init__(self, o1=None, o2=None, b1=-1, b2=-1, normal=None, pos=None, penetration_depth=0.0):
        self.o1, self.o2, self.b1, self.b2 = o1, o2, b1, b2
        self.normal = np.zeros(3) if normal is None else normal
        self.pos = np.zeros(3) if pos is None else pos
        self.penetration_depth = penetration_depth


class CostSource:
    def __init__(self, aabb_min=None, aabb_max=None, cost_density=0.0, total_cost=0.0):
        self.aabb_min, self.aabb_max = aabb_min, aabb_max
        self.cost_density, self.total_cost = cost_density, total_cost


class CollisionRequest:
    def __init__(self, num_max_contacts=1, enable_contact=False, num_max_cost_sources=1, enable_cost=False,
                 use_approximate_cost=True, gjk_solver_type=GJKSolverType.GST_LIBCCD):
        self.num_max_contacts = num_max_contacts
        self.enable_contact = enable_contact
        self.num_max_cost_sources = num_max_cost_sources
        self.enable_cost = enable_cost
        self.use_approximate_cost = use_approximate_cost
        self.gjk_solver_type = gjk_solver_type


class CollisionResult:
    def __init__(self):
        self.contacts = []
        self.cost_sources = []
        self.is_collision = False


class DistanceRequest:
    def __init__(self, enable_nearest_points=False, enable_signed_distance=False,
                 gjk_solver_type=GJKSolverType.GST_LIBCCD, rel_err=0.0, abs_err=0.0, distance_tolerance=1e-6):
        self.enable_nearest_points = enable_nearest_points
        self.enable_signed_distance = enable_signed_distance
        self.gjk_solver_type = gjk_solver_type
        self.rel_err, self.abs_err = rel_err, abs_err
        self.distance_tolerance = distance_tolerance


class DistanceResult:
    def __init__(self, min_distance_=sys.float_info.max):
        self.min_distance = min_distance_
        self.nearest_points = [np.zeros(3), np.zeros(3)]
        self.o1 = self.o2 = None
        self.b1 = self.b2 = -1


class CollisionData:
    def __init__(self, request=None, result=None):
        self.request = CollisionRequest() if request is None else request
        self.result = CollisionResult() if result is None else result
        self.done = False


class DistanceData:
    def __init__(self, request=None, result=None):
        self.request = DistanceRequest() if request is None else request
        self.result = DistanceResult() if result is None else result
        self.done = False


def _pair_contacts(o1, o2, limit):
    """Contacts of two collision objects (at most `limit`), in python-fcl's form."""
    g1, g2 = o1.geom, o2.geom
    if g1._surface or g2._surface:
        # A plane surface: both half-spaces must be reached; the contact is the deeper side's.
        surface, other, swap = (o1, o2, False) if g1._surface else (o2, o1, True)
        (ga, pa), (gb, pb) = surface._parts()
        deepest = None
        for g, p in other._parts():
            if not (_gq.overlap(ga, pa, g, p) and _gq.overlap(gb, pb, g, p)):
                continue
            da, db = _gq.distance(ga, pa, g, p), _gq.distance(gb, pb, g, p)
            d = da if da.distance > db.distance else db
            if deepest is None or d.distance < deepest.distance:
                deepest = d
        if deepest is None:
            return []
        normal = -deepest.normal if swap else deepest.normal
        return [Contact(o1.geom, o2.geom, -1, -1, normal, (deepest.point0 + deepest.point1) * 0.5,
                        max(0.0, -deepest.distance))]
    contacts = []
    for ga, pa in o1._parts():
        for gb, pb in o2._parts():
            if g1._is_mesh and g2._is_mesh:
                # One contact per crossing triangle pair, along the shallower of its two face normals (gq's normal
                # points from mesh 2 to mesh 1; python-fcl's from o1 to o2).
                for c in _gq.mesh_contacts(ga, pa, gb, pb, max_contacts=limit):
                    contacts.append(Contact(g1, g2, c.triangle0, c.triangle1, -c.normal, c.position, c.depth))
                continue
            if not _gq.overlap(ga, pa, gb, pb):
                continue
            d = _gq.distance(ga, pa, gb, pb)
            b1 = b2 = -1
            if g1._is_mesh or g2._is_mesh:
                mesh_side = 0 if g1._is_mesh else 1
                # The triangle nearest to the other shape: its index goes to b1 / b2.
                mesh, mpose = (ga, pa) if mesh_side == 0 else (gb, pb)
                point = d.point1 if mesh_side == 1 else d.point0
                _, _, tri = _gq.point_distance(point, mesh, mpose)
                b1, b2 = (tri, -1) if mesh_side == 0 else (-1, tri)
            contacts.append(Contact(g1, g2, b1, b2, d.normal, (d.point0 + d.point1) * 0.5, max(0.0, -d.distance)))
    return contacts[:limit]


def collide(o1, o2, request=None, result=None):
    """Whether o1 and o2 collide: the number of contacts (at most request.num_max_contacts), appended to result."""
    request = CollisionRequest() if request is None else request
    result = CollisionResult() if result is None else result
    limit = max(1, int(request.num_max_contacts))
    contacts = _pair_contacts(o1, o2, limit)
    if contacts:
        result.is_collision = True
        room = max(0, limit - len(result.contacts))
        result.contacts.extend(contacts[:room] if room else [])
    return len(contacts)


def distance(o1, o2, request=None, result=None):
    """Distance between o1 and o2; for a colliding pair -1, or minus the penetration depth when the request enables
    signed distance. The result keeps the smallest."""
    request = DistanceRequest() if request is None else request
    result = DistanceResult() if result is None else result
    best = None
    parts1, parts2 = o1._parts(), o2._parts()
    if o1.geom._surface or o2.geom._surface:
        surface, other, swap = (o1, o2, False) if o1.geom._surface else (o2, o1, True)
        (ga, pa), (gb, pb) = surface._parts()
        for g, p in other._parts():
            da, db = _gq.distance(ga, pa, g, p), _gq.distance(gb, pb, g, p)
            d = da if da.distance > db.distance else db
            pts = (d.point1, d.point0) if swap else (d.point0, d.point1)
            if best is None or d.distance < best[0]:
                best = (d.distance, pts)
    else:
        for ga, pa in parts1:
            for gb, pb in parts2:
                d = _gq.distance(ga, pa, gb, pb)
                if best is None or d.distance < best[0]:
                    best = (d.distance, (d.point0, d.point1))
    dist, points = best
    if dist < 0 and not request.enable_signed_distance:
        dist, points = -1.0, (np.zeros(3), np.zeros(3))
    if dist < result.min_distance:
        result.min_distance = dist
        result.nearest_points = [np.array(points[0]), np.array(points[1])]
        result.o1, result.o2 = o1.geom, o2.geom
        result.b1 = result.b2 = -1
    return dist


class ContinuousCollisionRequest:
    def __init__(self, num_max_iterations=10, toc_err=0.0001, ccd_motion_type=CCDMotionType.CCDM_TRANS,
                 gjk_solver_type=GJKSolverType.GST_LIBCCD, ccd_solver_type=CCDSolverType.CCDC_CONSERVATIVE_ADVANCEMENT):
        self.num_max_iterations = num_max_iterations
        self.toc_err = toc_err
        self.ccd_motion_type = ccd_motion_type
        self.gjk_solver_type = gjk_solver_type
        self.ccd_solver_type = ccd_solver_type


class ContinuousCollisionResult:
    def __init__(self, is_collide=False, time_of_contact=1.0):
        self.is_collide = is_collide
        self.time_of_contact = time_of_contact


def _part_contact_time(ga, pa, gb, pb, motion):
    """When geometry a, translated by `motion` over t in [0, 1], first touches b (fixed): t, or None. A sweep of
    whichever of the two gq can move (the other way round along -motion when a cannot)."""
    if _gq.overlap(ga, pa, gb, pb):
        return 0.0
    length = float(np.linalg.norm(motion))
    if length == 0.0:
        return None
    direction = motion / length
    try:
        hit = _gq.sweep(direction, length, ga, pa, gb, pb)
    except _gq.UnsupportedError:
        hit = _gq.sweep(-direction, length, gb, pb, ga, pa)
    return None if hit is None else min(1.0, hit.distance / length)


def _translation_contact_time(o1, o2, motion):
    """First t in [0, 1] at which o1, translated by `motion`, touches o2 (fixed), or None. A Plane surface is touched
    when the other object reaches both of its closed half-spaces."""
    def latest(times):
        return None if any(t is None for t in times) else max(times)

    def earliest(times):
        times = [t for t in times if t is not None]
        return min(times) if times else None

    if o1.geom._surface or o2.geom._surface:
        surface, other, sign = (o1, o2, -1.0) if o1.geom._surface else (o2, o1, 1.0)
        return earliest([latest([_part_contact_time(g, p, h, q, sign * motion) for h, q in surface._parts()])
                         for g, p in other._parts()])
    return earliest([_part_contact_time(ga, pa, gb, pb, motion) for ga, pa in o1._parts() for gb, pb in o2._parts()])


def _aligned_half_angle(a, b):
    """b's quaternion turned to a's hemisphere (the same rotation) and the half angle between them, arccos(qa . qb)."""
    qa, qb = a.getQuatRotation(), b.getQuatRotation()
    dot = float(np.dot(qa, qb))
    if dot < 0:
        qb, dot = -qb, -dot
    return qb, np.arccos(min(1.0, dot))


def _slerp_transform(a, b, t):
    """The transform at t in [0, 1] of the linear motion from a to b (translation lerp, rotation slerp)."""
    qa, (qb, angle) = a.getQuatRotation(), _aligned_half_angle(a, b)
    if angle < 1e-12:
        q = qa
    else:
        q = (np.sin((1 - t) * angle) * qa + np.sin(t * angle) * qb) / np.sin(angle)
    return Transform(q, (1 - t) * a.getTranslation() + t * b.getTranslation())


def _rotation_angle(a, b):
    """The angle of the rotation taking transform a's orientation to b's."""
    return 2.0 * _aligned_half_angle(a, b)[1]


def _conservative_advancement(o1, tf1_end, o2, tf2_end, request):
    """Linear motions with rotation: advance t by distance / (bound on how fast any point of one object approaches
    the other: relative translation plus each rotation angle times the object's radius about its origin) until the
    objects are within toc_err."""
    a0, b0 = o1._tf, o2._tf

    def radius(obj):
        lo, hi = obj._aabb()
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
        return float(np.max(np.linalg.norm(corners - obj._tf.getTranslation(), axis=1)))

    speed = (np.linalg.norm((tf1_end.getTranslation() - a0.getTranslation()) -
                            (tf2_end.getTranslation() - b0.getTranslation())) +
             _rotation_angle(a0, tf1_end) * radius(o1) + _rotation_angle(b0, tf2_end) * radius(o2))
    signed = DistanceRequest(enable_signed_distance=True)
    t = 0.0
    for _ in range(max(int(request.num_max_iterations), 1000)):
        c1 = CollisionObject(o1.geom, _slerp_transform(a0, tf1_end, t))
        c2 = CollisionObject(o2.geom, _slerp_transform(b0, tf2_end, t))
        d = distance(c1, c2, signed)
        if d <= request.toc_err:
            return t
        if speed == 0.0:
            return None
        t += d / speed
        if t > 1.0:
            return None
    return t


def continuousCollide(o1, tf1_end, o2, tf2_end, request=None, result=None):
    """Whether o1 and o2 collide while moving from their transforms to tf1_end / tf2_end: the time of contact
    (1.0 when they do not), kept in result as python-fcl does. CCDM_TRANS (and CCDM_LINEAR without rotation) is exact:
    a gq sweep of the relative translation. CCDM_LINEAR with rotation is conservative advancement on gq's exact
    distance, within request.toc_err. Screw and spline motions raise UnsupportedError."""
    request = ContinuousCollisionRequest() if request is None else request
    result = ContinuousCollisionResult() if result is None else result
    tf1_end, tf2_end = Transform(tf1_end), Transform(tf2_end)
    motion_type = request.ccd_motion_type
    if motion_type not in (CCDMotionType.CCDM_TRANS, CCDMotionType.CCDM_LINEAR):
        raise _gq.UnsupportedError("continuousCollide: only CCDM_TRANS and CCDM_LINEAR motions are supported")
    rotates = motion_type == CCDMotionType.CCDM_LINEAR and (
        not np.array_equal(o1._tf.getRotation(), tf1_end.getRotation()) or
        not np.array_equal(o2._tf.getRotation(), tf2_end.getRotation()))
    if rotates:
        toc = _conservative_advancement(o1, tf1_end, o2, tf2_end, request)
    else:
        # Translations only (CCDM_TRANS keeps the start rotations): o1 moves relative to o2 by the difference.
        motion = (tf1_end.getTranslation() - o1._tf.getTranslation()) - (tf2_end.getTranslation() - o2._tf.getTranslation())
        toc = _translation_contact_time(o1, o2, motion)
    if toc is None:
        return 1.0
    result.is_collide = True
    result.time_of_contact = min(result.time_of_contact, toc)
    return toc


def defaultCollisionCallback(o1, o2, cdata):
    """python-fcl's default: collide the pair into cdata.result; done once num_max_contacts are found."""
    request, result = cdata.request, cdata.result
    if cdata.done:
        return True
    collide(o1, o2, request, result)
    if not request.enable_cost and result.is_collision and len(result.contacts) >= request.num_max_contacts:
        cdata.done = True
    return cdata.done


def defaultDistanceCallback(o1, o2, cdata):
    """python-fcl's default: (done, distance so far); done once the objects touch."""
    request, result = cdata.request, cdata.result
    if cdata.done:
        return True, result.min_distance
    distance(o1, o2, request, result)
    dist = result.min_distance
    if dist <= 0:
        return True, dist
    return cdata.done, dist


class DynamicAABBTreeCollisionManager:
    """Broadphase over the registered objects' world AABBs; calls the callback on each candidate pair (collide:
    AABB-overlapping pairs; distance: pairs nearest AABB first, until the callback is done or no AABB is nearer than
    the distance found)."""

    def __init__(self):
        self._objs = []
        self._boxes = None

    def registerObjects(self, objs):
        self._objs.extend(objs)
        self._boxes = None

    def registerObject(self, obj):
        self._objs.append(obj)
        self._boxes = None

    def unregisterObject(self, obj):
        self._objs = [o for o in self._objs if o is not obj]
        self._boxes = None

    def setup(self):
        self._boxes = None
        self._bounds()

    def update(self, arg=None):
        self._boxes = None

    def clear(self):
        self._objs, self._boxes = [], None

    def empty(self):
        return not self._objs

    def size(self):
        return len(self._objs)

    def getObjects(self):
        return list(self._objs)

    def _bounds(self):
        if self._boxes is None or len(self._boxes[0]) != len(self._objs):
            boxes = [o._aabb() for o in self._objs]
            lo = np.array([b[0] for b in boxes]).reshape(-1, 3)
            hi = np.array([b[1] for b in boxes]).reshape(-1, 3)
            self._boxes = (lo, hi)
        return self._boxes

    def _candidates(self, other_objs, other_boxes, self_pairs):
        lo, hi = self._bounds()
        olo, ohi = other_boxes
        gap = np.maximum(0.0, np.maximum(lo[:, None, :] - ohi[None, :, :], olo[None, :, :] - hi[:, None, :]))
        gap = np.sqrt((gap ** 2).sum(axis=2))
        pairs = []
        for i in range(len(self._objs)):
            for j in range(i + 1 if self_pairs else 0, len(other_objs)):
                pairs.append((float(gap[i, j]), i, j))
        return pairs

    def _other(self, args):
        if args and isinstance(args[0], DynamicAABBTreeCollisionManager):
            return args[0].getObjects(), args[0]._bounds(), False, args[1:]
        if args and isinstance(args[0], CollisionObject):
            lo, hi = args[0]._aabb()
            return [args[0]], (lo[None, :], hi[None, :]), False, args[1:]
        return self._objs, self._bounds(), True, args

    def collide(self, *args):
        """collide(data, callback) | collide(obj, data, callback) | collide(manager, data, callback)."""
        objs, boxes, self_pairs, rest = self._other(args)
        if len(rest) != 2:
            raise TypeError("collide: expected ([object or manager,] data, callback)")
        data, callback = rest
        if not self._objs or not objs:
            return
        for gap, i, j in self._candidates(objs, boxes, self_pairs):
            if gap > 0:
                continue
            if callback(self._objs[i], objs[j], data):
                return

    def distance(self, *args):
        """distance(data, callback) | distance(obj, data, callback) | distance(manager, data, callback)."""
        objs, boxes, self_pairs, rest = self._other(args)
        if len(rest) != 2:
            raise TypeError("distance: expected ([object or manager,] data, callback)")
        data, callback = rest
        if not self._objs or not objs:
            return
        best = np.inf
        for gap, i, j in sorted(self._candidates(objs, boxes, self_pairs)):
            if gap > best:
                break
            done, dist = callback(self._objs[i], objs[j], data)
            best = min(best, dist)
            if done:
                return
