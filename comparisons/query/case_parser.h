#pragma once
// Case-file line -> Case. Errors name the line and the field: "line 3: field 'geom.radius': expected a number".
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "case.h"

namespace gq::cases {

class CaseParser {
 public:
  // Relative mesh paths are resolved against `baseDir` (the case file's folder).
  explicit CaseParser(std::string baseDir);

  // Parses the text of line number `line` (1-based). On failure returns false, fills `error`, and leaves in `id`
  // whatever id could be read (null otherwise), so the output line can still carry it.
  bool parse(const std::string& text, std::size_t line, Case& out, nlohmann::json& id, std::string& error);

 private:
  struct LoadedMesh {
    std::vector<Vec3d> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
  };
  const LoadedMesh& loadMesh(const std::string& file, const std::string& field);
  ShapeDesc readShape(const nlohmann::json& v, const std::string& path);
  void readConvex(const nlohmann::json& v, const std::string& path, ShapeDesc& s);
  void readMesh(const nlohmann::json& v, const std::string& path, ShapeDesc& s);
  void readHeightField(const nlohmann::json& v, const std::string& path, ShapeDesc& s);
  void readQuery(const nlohmann::json& v, Case& c);

  std::string baseDir_;
  std::map<std::string, LoadedMesh> meshFiles_;  // each file is read once per case file
};

}  // namespace gq::cases
