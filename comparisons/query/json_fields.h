#pragma once
// Typed readers for case-file fields. Each names the field by its dotted path ("pose0.q") and throws FieldError
// on a missing field or wrong type; the parser catches it per line (nothing escapes the runner).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case.h"

namespace gq::cases {

struct FieldError : std::runtime_error {
  FieldError(std::string field, const std::string& message)
      : std::runtime_error(message), field(std::move(field)) {}
  std::string field;
};

using Json = nlohmann::json;

std::string joinPath(const std::string& path, const char* key);
// The member `key` of object `obj`; FieldError "missing" if absent.
const Json& requireMember(const Json& obj, const std::string& path, const char* key);
// The member or nullptr.
const Json* findMember(const Json& obj, const char* key);

double readNumber(const Json& v, const std::string& field);  // finite number
double readNonNegative(const Json& v, const std::string& field);
std::uint32_t readIndex(const Json& v, const std::string& field);  // integer in [0, 2^32)
bool readBool(const Json& v, const std::string& field);
std::string readString(const Json& v, const std::string& field);
Vec3d readVec3(const Json& v, const std::string& field);
Quatd readUnitQuat(const Json& v, const std::string& field);  // [x,y,z,w], normalized; zero norm is an error
PoseDesc readPose(const Json& v, const std::string& field);   // {"p","q"}, both optional
std::vector<Vec3d> readVec3List(const Json& v, const std::string& field);
std::uint16_t readHitFlags(const Json& v, const std::string& field);  // list of kHitFlagNames

// Optional member helpers: the default when absent.
double numberOr(const Json& obj, const std::string& path, const char* key, double fallback);

}  // namespace gq::cases
