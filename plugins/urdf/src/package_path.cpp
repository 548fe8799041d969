// Mesh URI resolution as ROS tools do it: package://<pkg>/<rest> looks for <dir>/<pkg>/<rest> in the given search
// folders, then in every folder of ROS_PACKAGE_PATH (and, as catkin workspaces nest packages, one level below);
// file:// takes an absolute path; anything else is a path relative to the URDF's folder.
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "gq/urdf/robot.h"

namespace gq::urdf {
namespace {

namespace fs = std::filesystem;

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::vector<std::string> rosPackagePath() {
  std::vector<std::string> dirs;
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  if (!env) return dirs;
  std::stringstream ss(env);
  for (std::string item; std::getline(ss, item, ':');)
    if (!item.empty()) dirs.push_back(item);
  return dirs;
}

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

// <root>/<pkg>/<rest>, or <root>/<any>/<pkg>/<rest> (a package one level below a search folder).
bool findInRoot(const fs::path& root, const std::string& pkg, const std::string& rest, std::string& path) {
  const fs::path direct = root / pkg / rest;
  if (isFile(direct)) {
    path = direct.string();
    return true;
  }
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path nested = it->path() / pkg / rest;
    if (it->is_directory(ec) && isFile(nested)) {
      path = nested.string();
      return true;
    }
  }
  return false;
}

Status resolvePackage(const std::string& uri, const LoadOptions& options, std::string& path) {
  const std::string body = uri.substr(std::string("package://").size());
  const auto slash = body.find('/');
  if (slash == std::string::npos || slash == 0)
    return Status::owned(StatusCode::ParseError, "malformed package URI '" + uri + "' (expected package://<package>/<path>)");
  const std::string pkg = body.substr(0, slash), rest = body.substr(slash + 1);
  std::vector<std::string> roots = options.packagePaths;
  if (options.useRosPackagePath)
    for (auto& d : rosPackagePath()) roots.push_back(d);
  for (const auto& root : roots)
    if (findInRoot(root, pkg, rest, path)) return {};
  std::string searched;
  for (const auto& root : roots) searched += (searched.empty() ? "" : ", ") + root;
  return Status::owned(StatusCode::FileError, "mesh file '" + uri + "' not found: package '" + pkg + "' searched in [" + searched +
                           "] (add --package-path or set ROS_PACKAGE_PATH)");
}

}  // namespace

Status resolveMeshPath(const std::string& uri, const std::string& baseDir, const LoadOptions& options,
                       std::string& path) {
  if (startsWith(uri, "package://")) return resolvePackage(uri, options, path);
  fs::path p = startsWith(uri, "file://") ? fs::path(uri.substr(7)) : fs::path(uri);
  if (p.is_relative()) p = fs::path(baseDir) / p;
  if (!isFile(p)) return Status::owned(StatusCode::FileError, "mesh file '" + uri + "' not found (looked at " + p.string() + ")");
  path = p.string();
  return {};
}

}  // namespace gq::urdf
