#include "json_fields.h"

#include <cmath>
#include <limits>

namespace gq::cases {

std::string joinPath(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }

const Json* findMember(const Json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const Json& requireMember(const Json& obj, const std::string& path, const char* key) {
  if (!obj.is_object()) throw FieldError(path, "expected an object");
  const Json* m = findMember(obj, key);
  if (m == nullptr) throw FieldError(joinPath(path, key), "missing");
  return *m;
}

double readNumber(const Json& v, const std::string& field) {
  if (!v.is_number()) throw FieldError(field, "expected a number, got " + std::string(v.type_name()));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw FieldError(field, "not finite");
  return x;
}

double readNonNegative(const Json& v, const std::string& field) {
  const double x = readNumber(v, field);
  if (x < 0) throw FieldError(field, "must be >= 0");
  return x;
}

std::uint32_t readIndex(const Json& v, const std::string& field) {
  if (!v.is_number_integer()) throw FieldError(field, "expected a non-negative integer, got " + std::string(v.type_name()));
  if (v.is_number_unsigned()) {
    const auto x = v.get<std::uint64_t>();
    if (x <= std::numeric_limits<std::uint32_t>::max()) return static_cast<std::uint32_t>(x);
  }
  throw FieldError(field, "expected an integer in [0, 4294967295]");
}

bool readBool(const Json& v, const std::string& field) {
  if (!v.is_boolean()) throw FieldError(field, "expected true or false, got " + std::string(v.type_name()));
  return v.get<bool>();
}

std::string readString(const Json& v, const std::string& field) {
  if (!v.is_string()) throw FieldError(field, "expected a string, got " + std::string(v.type_name()));
  return v.get<std::string>();
}

namespace {
std::vector<double> readNumbers(const Json& v, const std::string& field, std::size_t count) {
  if (!v.is_array() || v.size() != count)
    throw FieldError(field, "expected an array of " + std::to_string(count) + " numbers");
  std::vector<double> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = readNumber(v[i], field + "[" + std::to_string(i) + "]");
  return out;
}
}  // namespace

Vec3d readVec3(const Json& v, const std::string& field) {
  const std::vector<double> x = readNumbers(v, field, 3);
  return Vec3d(x[0], x[1], x[2]);
}

Quatd readUnitQuat(const Json& v, const std::string& field) {
  const std::vector<double> x = readNumbers(v, field, 4);
  Quatd q(x[3], x[0], x[1], x[2]);  // file order x, y, z, w
  const double n = q.norm();
  if (!(n > 0)) throw FieldError(field, "quaternion has zero length");
  q.coeffs() /= n;
  return q;
}

PoseDesc readPose(const Json& v, const std::string& field) {
  if (!v.is_object()) throw FieldError(field, "expected an object {\"p\":[x,y,z],\"q\":[x,y,z,w]}");
  PoseDesc pose;
  if (const Json* p = findMember(v, "p")) pose.p = readVec3(*p, field + ".p");
  if (const Json* q = findMember(v, "q")) pose.q = readUnitQuat(*q, field + ".q");
  return pose;
}

std::vector<Vec3d> readVec3List(const Json& v, const std::string& field) {
  if (!v.is_array()) throw FieldError(field, "expected an array of [x,y,z]");
  std::vector<Vec3d> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out.push_back(readVec3(v[i], field + "[" + std::to_string(i) + "]"));
  return out;
}

std::uint16_t readHitFlags(const Json& v, const std::string& field) {
  if (!v.is_array()) throw FieldError(field, "expected an array of flag names");
  std::uint16_t bits = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string name = readString(v[i], field + "[" + std::to_string(i) + "]");
    bool known = false;
    for (std::size_t b = 0; b < kHitFlagNames.size(); ++b) {
      if (name == kHitFlagNames[b]) {
        bits |= static_cast<std::uint16_t>(1u << b);
        known = true;
      }
    }
    if (!known) throw FieldError(field + "[" + std::to_string(i) + "]", "unknown hit flag '" + name + "'");
  }
  return bits;
}

double numberOr(const Json& obj, const std::string& path, const char* key, double fallback) {
  const Json* m = findMember(obj, key);
  return m == nullptr ? fallback : readNumber(*m, joinPath(path, key));
}

}  // namespace gq::cases
