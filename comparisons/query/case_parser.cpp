#include "case_parser.h"

#include <filesystem>
#include <limits>

#include "gq/cooking.h"
#include "gq/hit.h"
#include "gq/io.h"
#include "gq/tolerances.h"
#include "json_fields.h"

namespace gq::cases {

const char* toString(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Capsule: return "capsule";
    case ShapeKind::Box: return "box";
    case ShapeKind::Plane: return "plane";
    case ShapeKind::Convex: return "convex";
    case ShapeKind::Mesh: return "mesh";
    case ShapeKind::HeightField: return "heightfield";
    case ShapeKind::Cylinder: return "cylinder";
    case ShapeKind::Cone: return "cone";
  }
  return "unknown";
}

const char* toString(QueryKind kind) {
  switch (kind) {
    case QueryKind::Raycast: return "raycast";
    case QueryKind::Overlap: return "overlap";
    case QueryKind::Penetration: return "penetration";
    case QueryKind::Distance: return "distance";
    case QueryKind::PointDistance: return "pointDistance";
    case QueryKind::Sweep: return "sweep";
    case QueryKind::Bounds: return "bounds";
  }
  return "unknown";
}

namespace {

bool shapeKindFromName(const std::string& name, ShapeKind& kind) {
  for (ShapeKind k : {ShapeKind::Sphere, ShapeKind::Capsule, ShapeKind::Box, ShapeKind::Plane, ShapeKind::Convex,
                      ShapeKind::Mesh, ShapeKind::HeightField, ShapeKind::Cylinder, ShapeKind::Cone}) {
    if (name == toString(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

bool queryKindFromName(const std::string& name, QueryKind& kind) {
  for (QueryKind k : {QueryKind::Raycast, QueryKind::Overlap, QueryKind::Penetration, QueryKind::Distance,
                      QueryKind::PointDistance, QueryKind::Sweep, QueryKind::Bounds}) {
    if (name == toString(k)) {
      kind = k;
      return true;
    }
  }
  return false;
}

ScaleDesc readScale(const Json& v, const std::string& field) {
  if (!v.is_object()) throw FieldError(field, "expected an object {\"s\":[x,y,z],\"q\":[x,y,z,w]}");
  ScaleDesc s;
  if (const Json* f = findMember(v, "s")) s.s = readVec3(*f, field + ".s");
  if (const Json* q = findMember(v, "q")) s.q = readUnitQuat(*q, field + ".q");
  return s;
}

std::vector<std::array<std::uint32_t, 3>> readTriangles(const Json& v, const std::string& field) {
  if (!v.is_array()) throw FieldError(field, "expected an array of index triples");
  std::vector<std::array<std::uint32_t, 3>> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    if (!v[i].is_array() || v[i].size() != 3) throw FieldError(f, "expected 3 vertex indices");
    for (std::size_t k = 0; k < 3; ++k) out[i][k] = readIndex(v[i][k], f);
  }
  return out;
}

// The cooked data depends on these fields only; instance fields (scale, flags, heightfield scales) are dropped.
std::string cookKeyOf(const Json& geom, const std::string& baseDir) {
  Json key = geom;
  for (const char* instanceField : {"scale", "doubleSided", "rowScale", "columnScale", "heightScale"})
    key.erase(instanceField);
  key["baseDir"] = baseDir;  // the same relative file name in another folder is another mesh
  return key.dump();
}

}  // namespace

CaseParser::CaseParser(std::string baseDir) : baseDir_(std::move(baseDir)) {}

const CaseParser::LoadedMesh& CaseParser::loadMesh(const std::string& file, const std::string& field) {
  std::filesystem::path path(file);
  if (path.is_relative()) path = std::filesystem::path(baseDir_) / path;
  const std::string key = path.lexically_normal().string();
  if (auto it = meshFiles_.find(key); it != meshFiles_.end()) return it->second;
  MeshData<double> data;
  if (Status s = loadMeshFile<double>(key, data); !s.ok()) throw FieldError(field, s.detailedMessage());
  LoadedMesh mesh;
  mesh.vertices = std::move(data.vertices);
  mesh.triangles = std::move(data.triangles);
  return meshFiles_.emplace(key, std::move(mesh)).first->second;
}

void CaseParser::readConvex(const Json& v, const std::string& path, ShapeDesc& s) {
  if (const Json* pts = findMember(v, "points")) {
    s.points = readVec3List(*pts, joinPath(path, "points"));
  } else if (const Json* file = findMember(v, "file")) {
    const std::string field = joinPath(path, "file");
    s.points = loadMesh(readString(*file, field), field).vertices;
  } else {
    throw FieldError(joinPath(path, "points"), "missing (give points or file)");
  }
  if (const Json* sc = findMember(v, "scale")) s.scale = readScale(*sc, joinPath(path, "scale"));
}

void CaseParser::readMesh(const Json& v, const std::string& path, ShapeDesc& s) {
  if (const Json* file = findMember(v, "file")) {
    const std::string field = joinPath(path, "file");
    const LoadedMesh& mesh = loadMesh(readString(*file, field), field);
    s.points = mesh.vertices;
    s.triangles = mesh.triangles;
  } else if (const Json* verts = findMember(v, "vertices")) {
    s.points = readVec3List(*verts, joinPath(path, "vertices"));
    s.triangles = readTriangles(requireMember(v, path, "triangles"), joinPath(path, "triangles"));
  } else {
    throw FieldError(joinPath(path, "file"), "missing (give file or vertices + triangles)");
  }
  if (const Json* sc = findMember(v, "scale")) s.scale = readScale(*sc, joinPath(path, "scale"));
  if (const Json* ds = findMember(v, "doubleSided")) s.doubleSided = readBool(*ds, joinPath(path, "doubleSided"));
}

void CaseParser::readHeightField(const Json& v, const std::string& path, ShapeDesc& s) {
  s.rows = readIndex(requireMember(v, path, "rows"), joinPath(path, "rows"));
  s.columns = readIndex(requireMember(v, path, "columns"), joinPath(path, "columns"));
  const std::string heightsField = joinPath(path, "heights");
  const Json& heights = requireMember(v, path, "heights");
  if (!heights.is_array()) throw FieldError(heightsField, "expected an array of numbers");
  const std::uint64_t samples = std::uint64_t(s.rows) * s.columns;
  if (samples > tol::kMaxHeightFieldSamples) throw FieldError(joinPath(path, "rows"), "rows * columns is too large");
  if (heights.size() != samples)
    throw FieldError(heightsField, "expected rows * columns = " + std::to_string(samples) + " numbers, got " +
                                       std::to_string(heights.size()));
  s.heights.resize(heights.size());
  for (std::size_t i = 0; i < heights.size(); ++i)
    s.heights[i] = readNumber(heights[i], heightsField + "[" + std::to_string(i) + "]");
  s.rowScale = numberOr(v, path, "rowScale", 1.0);
  s.columnScale = numberOr(v, path, "columnScale", 1.0);
  s.heightScale = numberOr(v, path, "heightScale", 1.0);
  if (const Json* holes = findMember(v, "holes")) {
    const std::string field = joinPath(path, "holes");
    if (!holes->is_array()) throw FieldError(field, "expected an array of cell indices");
    for (std::size_t i = 0; i < holes->size(); ++i)
      s.holes.push_back(readIndex((*holes)[i], field + "[" + std::to_string(i) + "]"));
  }
  if (const Json* ds = findMember(v, "doubleSided")) s.doubleSided = readBool(*ds, joinPath(path, "doubleSided"));
}

ShapeDesc CaseParser::readShape(const Json& v, const std::string& path) {
  if (!v.is_object()) throw FieldError(path, "expected a geometry object with a \"type\"");
  ShapeDesc s;
  const std::string typeField = joinPath(path, "type");
  const std::string type = readString(requireMember(v, path, "type"), typeField);
  if (!shapeKindFromName(type, s.kind)) throw FieldError(typeField, "unknown geometry type '" + type + "'");
  const auto number = [&](const char* key) { return readNumber(requireMember(v, path, key), joinPath(path, key)); };
  switch (s.kind) {
    case ShapeKind::Sphere: s.radius = number("radius"); break;
    case ShapeKind::Capsule:
    case ShapeKind::Cylinder:
    case ShapeKind::Cone:
      s.radius = number("radius");
      s.halfHeight = number("halfHeight");
      break;
    case ShapeKind::Box: s.halfExtents = readVec3(requireMember(v, path, "halfExtents"), joinPath(path, "halfExtents")); break;
    case ShapeKind::Plane: break;
    case ShapeKind::Convex: readConvex(v, path, s); break;
    case ShapeKind::Mesh: readMesh(v, path, s); break;
    case ShapeKind::HeightField: readHeightField(v, path, s); break;
  }
  s.cookKey = cookKeyOf(v, baseDir_);
  return s;
}

void CaseParser::readQuery(const Json& v, Case& c) {
  const auto shape = [&](const char* key) { return readShape(requireMember(v, "", key), key); };
  const auto pose = [&](const char* key) {
    const Json* p = findMember(v, key);
    return p == nullptr ? PoseDesc() : readPose(*p, key);
  };
  const auto vec = [&](const char* key) { return readVec3(requireMember(v, "", key), key); };
  const auto flags = [&](std::uint16_t fallback) {
    const Json* f = findMember(v, "flags");
    return f == nullptr ? fallback : readHitFlags(*f, "flags");
  };
  // maxDist may be omitted: unbounded.
  const double unbounded = std::numeric_limits<double>::infinity();
  switch (c.query) {
    case QueryKind::Raycast: {
      RaycastCase r;
      r.geom = shape("geom");
      r.pose = pose("pose");
      r.origin = vec("origin");
      r.dir = vec("dir");
      const Json* md = findMember(v, "maxDist");
      r.maxDist = md == nullptr ? unbounded : readNonNegative(*md, "maxDist");
      r.flags = flags(kDefaultHitFlags.bits());
      if (const Json* mh = findMember(v, "maxHits")) r.maxHits = readIndex(*mh, "maxHits");
      if (r.maxHits == 0) throw FieldError("maxHits", "must be >= 1");
      c.input = std::move(r);
      break;
    }
    case QueryKind::Overlap:
    case QueryKind::Penetration:
    case QueryKind::Distance: {
      PairCase p;
      p.geom0 = shape("geom0");
      p.pose0 = pose("pose0");
      p.geom1 = shape("geom1");
      p.pose1 = pose("pose1");
      c.input = std::move(p);
      break;
    }
    case QueryKind::PointDistance: {
      PointDistanceCase p;
      p.point = vec("point");
      p.geom = shape("geom");
      p.pose = pose("pose");
      c.input = std::move(p);
      break;
    }
    case QueryKind::Sweep: {
      SweepCase s;
      s.geom0 = shape("geom0");
      s.pose0 = pose("pose0");
      s.geom1 = shape("geom1");
      s.pose1 = pose("pose1");
      s.dir = vec("dir");
      s.maxDist = readNonNegative(requireMember(v, "", "maxDist"), "maxDist");
      s.flags = flags(kDefaultHitFlags.bits());
      s.inflation = numberOr(v, "", "inflation", 0.0);
      c.input = std::move(s);
      break;
    }
    case QueryKind::Bounds: {
      BoundsCase b;
      b.geom = shape("geom");
      b.pose = pose("pose");
      b.offset = numberOr(v, "", "offset", 0.0);
      b.inflation = numberOr(v, "", "inflation", tol::kDefaultBoundsInflation);
      c.input = std::move(b);
      break;
    }
  }
}

bool CaseParser::parse(const std::string& text, std::size_t line, Case& out, Json& id, std::string& error) {
  id = nullptr;
  const std::string where = "line " + std::to_string(line) + ": ";
  Json v;
  try {
    v = Json::parse(text);
  } catch (const Json::parse_error& e) {
    error = where + "invalid JSON at byte " + std::to_string(e.byte);
    return false;
  } catch (const Json::exception& e) {  // e.g. out_of_range 406: a number beyond the double range (1e999)
    error = where + "invalid JSON: " + e.what();
    return false;
  }
  if (!v.is_object()) {
    error = where + "expected a JSON object, got " + std::string(v.type_name());
    return false;
  }
  try {
    id = requireMember(v, "", "id");
    Case c;
    c.line = line;
    c.id = id;
    if (const Json* p = findMember(v, "precision")) {
      const std::string name = readString(*p, "precision");
      if (name == "float") c.precision = Precision::Float;
      else if (name == "double") c.precision = Precision::Double;
      else throw FieldError("precision", "expected \"float\" or \"double\", got '" + name + "'");
    }
    const std::string query = readString(requireMember(v, "", "query"), "query");
    if (!queryKindFromName(query, c.query)) throw FieldError("query", "unknown query '" + query + "'");
    readQuery(v, c);
    out = std::move(c);
    return true;
  } catch (const FieldError& e) {
    error = where + "field '" + e.field + "': " + e.what();
  } catch (const std::exception& e) {  // e.g. allocation failure on an absurd size
    error = where + e.what();
  }
  return false;
}

}  // namespace gq::cases
