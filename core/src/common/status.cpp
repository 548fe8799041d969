#include "gq/status.h"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <new>

#include "gq/geometry.h"

namespace gq {
namespace {

// The heap block of an owned message: a reference count followed by the text. Status keeps a pointer to the text.
struct OwnedHeader {
  std::atomic<std::uint32_t> references;
};
constexpr std::size_t kTextOffset = alignof(std::max_align_t) > sizeof(OwnedHeader)
                                        ? alignof(std::max_align_t)
                                        : sizeof(OwnedHeader);

OwnedHeader* headerOf(const char* text) {
  return reinterpret_cast<OwnedHeader*>(const_cast<char*>(text) - kTextOffset);
}

const char* customIssueText(std::uint16_t issue) {
  switch (CustomIssue(issue)) {
    case CustomIssue::NonConvexOverlap:
      return "overlap with a non-convex custom geometry (only raycast and bounds are available for it)";
    case CustomIssue::NonConvexPenetration:
      return "penetration with a non-convex custom geometry (only raycast and bounds are available for it)";
    case CustomIssue::BadPenetration:
      return "a custom geometry returned a non-finite, negative or non-unit penetration";
    case CustomIssue::BadDistance:
      return "a custom geometry returned a non-finite distance or a normal that is not unit";
    case CustomIssue::BadSweepHit:
      return "a custom geometry returned an invalid sweep hit (non-finite, non-unit normal or outside [0, maxDist])";
  }
  return "a custom geometry failed";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

const char* toString(StatusCode code) noexcept {
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

const char* Status::message() const noexcept {
  if (detail_ == Detail::CustomName) return customIssueText(small_);
  return text_ ? text_ : "";
}

Status Status::aboutCustom(StatusCode c, CustomIssue issue, const char* name) noexcept {
  Status s(c, name ? name : "");
  s.detail_ = Detail::CustomName;
  s.small_ = std::uint16_t(issue);
  return s;
}

Status Status::owned(StatusCode c, const char* text) noexcept {
  if (!text) text = "";
  const std::size_t size = std::strlen(text);
  void* block = ::operator new(kTextOffset + size + 1, std::nothrow);
  if (!block) return Status(c, "the message of this status could not be allocated");
  new (block) OwnedHeader{{1u}};
  char* copy = static_cast<char*>(block) + kTextOffset;
  std::memcpy(copy, text, size + 1);
  Status s(c, copy);
  s.detail_ = Detail::Owned;
  return s;
}

void Status::retain() const noexcept { headerOf(text_)->references.fetch_add(1, std::memory_order_relaxed); }

void Status::release() noexcept {
  OwnedHeader* h = headerOf(text_);
  if (h->references.fetch_sub(1, std::memory_order_acq_rel) == 1) {
    h->~OwnedHeader();
    ::operator delete(static_cast<void*>(h));
  }
}

std::string Status::toString() const {
  const std::string m = detailedMessage();
  return m.empty() ? std::string(gq::toString(code)) : gq::toString(code) + (": " + m);
}

std::string Status::detailedMessage() const {
  std::string s = message();
  switch (detail_) {
    case Detail::None:
    case Detail::Owned: break;
    case Detail::Index: s += " (index " + std::to_string(number_.index) + ")"; break;
    case Detail::Length: s += " (length " + number(number_.value) + ")"; break;
    case Detail::Norm: s += " (norm " + number(number_.value) + ")"; break;
    case Detail::Iterations:
      s += " (after " + std::to_string(small_) + " iterations, error bound " + number(number_.value) + ")";
      break;
    case Detail::Type: s += std::string(" (") + gq::toString(GeometryType(small_ & 0xFF)) + ")"; break;
    case Detail::TypePair:
      s += std::string(" (") + gq::toString(GeometryType(small_ & 0xFF)) + " and " +
           gq::toString(GeometryType(small_ >> 8)) + ")";
      break;
    case Detail::CustomName: s += std::string(" (custom geometry '") + text_ + "')"; break;
  }
  return s;
}

}  // namespace gq
