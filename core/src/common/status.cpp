#include "gq/status.h"

namespace gq {

const char* toString(StatusCode code) {
  switch (code) {
    case StatusCode::Ok: return "ok";
    case StatusCode::Warning: return "warning";
    case StatusCode::InvalidArgument: return "invalid argument";
    case StatusCode::Unsupported: return "unsupported";
    case StatusCode::DegenerateMesh: return "degenerate mesh";
    case StatusCode::FileError: return "file error";
    case StatusCode::ParseError: return "parse error";
    case StatusCode::NotConverged: return "not converged";
    case StatusCode::InternalError: return "internal error";
  }
  return "unknown";
}

std::string Status::toString() const {
  std::string s = gq::toString(code);
  if (!message.empty()) s += ": " + message;
  return s;
}

}  // namespace gq
