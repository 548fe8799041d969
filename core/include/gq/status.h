#pragma once
// Every public entry returns a Status: a code plus a human-readable message. Nothing throws across the API,
// and on any code other than Ok/Warning the outputs are left untouched.
#include <string>
#include <utility>

namespace gq {

enum class StatusCode {
  Ok = 0,
  Warning,          // the query ran; some input was ignored (e.g. incompatible hit flags): see message
  InvalidArgument,  // NaN/Inf, non-unit direction, negative distance or size, null output, bad flags
  Unsupported,      // the query is not defined for this pair of geometry types
  DegenerateMesh,   // empty mesh, all triangles degenerate, coplanar/collinear hull points
  FileError,        // missing or unreadable file
  ParseError,       // malformed file content
  NotConverged,     // an iterative solver hit its limit without a certified answer
  InternalError,    // a bug: an exception caught at the API boundary
};

const char* toString(StatusCode code);

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;

  Status() = default;
  Status(StatusCode c, std::string m) : code(c), message(std::move(m)) {}

  // Ok or Warning: the outputs were written.
  bool ok() const { return code == StatusCode::Ok || code == StatusCode::Warning; }
  explicit operator bool() const { return ok(); }

  static Status success() { return Status(); }
  static Status warning(std::string m) { return {StatusCode::Warning, std::move(m)}; }
  static Status invalid(std::string m) { return {StatusCode::InvalidArgument, std::move(m)}; }
  static Status unsupported(std::string m) { return {StatusCode::Unsupported, "unsupported: " + std::move(m)}; }
  static Status degenerate(std::string m) { return {StatusCode::DegenerateMesh, std::move(m)}; }
  static Status fileError(std::string m) { return {StatusCode::FileError, std::move(m)}; }
  static Status parseError(std::string m) { return {StatusCode::ParseError, std::move(m)}; }
  static Status notConverged(std::string m) { return {StatusCode::NotConverged, std::move(m)}; }
  static Status internal(std::string m) { return {StatusCode::InternalError, std::move(m)}; }

  std::string toString() const;
};

}  // namespace gq
