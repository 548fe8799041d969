#pragma once
// Every public entry returns a Status: a code plus a human-readable message. Nothing throws across the API,
// and on any code other than Ok/Warning the outputs are left untouched.
//
// A Status is 16 bytes and a query never allocates one: its message is static text (a string literal), and the
// details of a failure (an index, a length, the geometry types of a pair, a custom shape's name) are stored inline
// as numbers and formatted only by toString(). message() is the static text alone. Loading paths (mesh files,
// cooking, robot models), whose messages name files, joints and links, use Status::owned(), the one form that
// allocates: a reference-counted copy of the text, shared by the copies of the Status.
#include <cstdint>
#include <string>
#include <utility>

namespace gq {

enum class StatusCode : std::uint8_t {
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

const char* toString(StatusCode code) noexcept;

// What a custom shape cannot do or did wrong: the message of a Status naming the shape (Status::aboutCustom).
enum class CustomIssue : std::uint8_t {
  NonConvexOverlap,      // overlap with a non-convex custom shape (only raycast and bounds answer those)
  NonConvexPenetration,  // penetration with a non-convex custom shape
  BadPenetration,        // its penetration callback answered a non-finite, negative or non-unit penetration
  BadDistance,           // its distance callback answered a non-finite distance or a non-unit normal
  BadSweepHit,           // its sweep callback answered a non-finite hit, a non-unit normal or one beyond maxDist
};

struct [[nodiscard]] Status {
  // What the inline detail holds; toString() appends it to the message in parentheses.
  enum class Detail : std::uint8_t {
    None,
    Index,          // "(index 12)": an element of an input array (triangle, sample)
    Length,         // "(length 1.5)": a vector that should be unit
    Norm,           // "(norm 1.5)": a quaternion that should be unit
    Iterations,     // "(after 64 iterations, error bound 0.001)": an iterative solver's state when it stopped
    Type,           // "(triangle mesh)": the geometry type a query does not take
    TypePair,       // "(plane and heightfield)": the pair of geometry types a query does not take
    CustomName,     // "(custom geometry 'ball')": the name of a custom shape (CustomGeometryCallbacks::name)
    Owned,          // no detail: the message is an owned, reference-counted text (Status::owned)
  };

  StatusCode code = StatusCode::Ok;

  Status() noexcept = default;
  // `text` must be static (a string literal): the Status keeps the pointer.
  Status(StatusCode c, const char* text) noexcept : code(c), text_(text) {}
  Status(const Status& other) noexcept : Status(other.code, other.text_) { copyDetail(other); }
  Status(Status&& other) noexcept
      : code(other.code), detail_(other.detail_), small_(other.small_), number_(other.number_), text_(other.text_) {
    if (other.detail_ == Detail::Owned) other.dropOwned();  // the reference moves here
  }
  Status& operator=(const Status& other) noexcept {
    if (this != &other) {
      Status copy(other);
      swap(copy);
    }
    return *this;
  }
  Status& operator=(Status&& other) noexcept {
    Status moved(static_cast<Status&&>(other));
    swap(moved);
    return *this;
  }
  ~Status() {
    if (detail_ == Detail::Owned) release();
  }

  // Ok or Warning: the outputs were written.
  bool ok() const noexcept { return code == StatusCode::Ok || code == StatusCode::Warning; }
  explicit operator bool() const noexcept { return ok(); }

  // The static message ("" for a plain success). Details are not in it: see toString().
  const char* message() const noexcept;
  // "<code>: <message> (<detail>)", e.g. "invalid argument: ray direction is not a unit vector (length 1.5)".
  // Builds a std::string (which may throw std::bad_alloc, as any string); for reporting, never called by a query.
  // Everything else a Status does (construct, copy, move, destroy) is noexcept.
  std::string toString() const;
  // "<message> (<detail>)": toString() without the code, for a caller that wraps the message in its own.
  std::string detailedMessage() const;

  Detail detail() const noexcept { return detail_; }
  std::uint32_t index() const noexcept { return detail_ == Detail::Index ? number_.index : 0; }
  float value() const noexcept {
    return detail_ == Detail::Length || detail_ == Detail::Norm || detail_ == Detail::Iterations ? number_.value
                                                                                                 : 0.0f;
  }

  // Inline details, each replacing any other (an owned text keeps its text and ignores them).
  Status& withIndex(std::uint32_t i) noexcept { return setNumber(Detail::Index, i); }
  Status& withLength(float length) noexcept { return setValue(Detail::Length, length); }
  Status& withNorm(float norm) noexcept { return setValue(Detail::Norm, norm); }
  Status& withIterations(std::uint32_t iterations, float errorBound) noexcept {
    if (detail_ == Detail::Owned) return *this;
    setValue(Detail::Iterations, errorBound);
    small_ = iterations > 0xFFFFu ? std::uint16_t(0xFFFFu) : std::uint16_t(iterations);
    return *this;
  }
  // GeometryType values (gq/geometry.h), stored as bytes.
  template <class GeometryTypeT> Status& withType(GeometryTypeT t) noexcept {
    return setTypes(Detail::Type, std::uint8_t(t), 0);
  }
  template <class GeometryTypeT> Status& withTypes(GeometryTypeT t0, GeometryTypeT t1) noexcept {
    return setTypes(Detail::TypePair, std::uint8_t(t0), std::uint8_t(t1));
  }
  // The same message and detail under another code (e.g. a solver's NotConverged reported as a Warning).
  Status withCode(StatusCode c) const noexcept {
    Status s(*this);
    s.code = c;
    return s;
  }

  static Status success() noexcept { return Status(); }
  static Status warning(const char* m) noexcept { return {StatusCode::Warning, m}; }
  static Status invalid(const char* m) noexcept { return {StatusCode::InvalidArgument, m}; }
  static Status unsupported(const char* m) noexcept { return {StatusCode::Unsupported, m}; }
  static Status degenerate(const char* m) noexcept { return {StatusCode::DegenerateMesh, m}; }
  static Status fileError(const char* m) noexcept { return {StatusCode::FileError, m}; }
  static Status parseError(const char* m) noexcept { return {StatusCode::ParseError, m}; }
  static Status notConverged(const char* m) noexcept { return {StatusCode::NotConverged, m}; }
  static Status internal(const char* m) noexcept { return {StatusCode::InternalError, m}; }
  // A static message about the custom shape named `name` (a string literal by the CustomGeometryCallbacks::name
  // contract): message() describes `issue`, toString() adds the name.
  static Status aboutCustom(StatusCode c, CustomIssue issue, const char* name) noexcept;
  // A message composed at run time (file paths, joint and link names): the only form that allocates, for loading
  // paths. If the allocation fails, the message is a static text saying so; nothing throws.
  static Status owned(StatusCode c, const char* text) noexcept;
  static Status owned(StatusCode c, const std::string& text) noexcept { return owned(c, text.c_str()); }

  void swap(Status& other) noexcept {
    std::swap(code, other.code);
    std::swap(detail_, other.detail_);
    std::swap(small_, other.small_);
    std::swap(number_, other.number_);
    std::swap(text_, other.text_);
  }

 private:
  union Number {
    std::uint32_t index;
    float value;
  };

  void copyDetail(const Status& other) noexcept {
    detail_ = other.detail_;
    small_ = other.small_;
    number_ = other.number_;
    if (detail_ == Detail::Owned) retain();
  }
  Status& setNumber(Detail d, std::uint32_t i) noexcept {
    if (detail_ == Detail::Owned) return *this;
    detail_ = d;
    number_.index = i;
    return *this;
  }
  Status& setValue(Detail d, float v) noexcept {
    if (detail_ == Detail::Owned) return *this;
    detail_ = d;
    number_.value = v;
    return *this;
  }
  Status& setTypes(Detail d, std::uint8_t t0, std::uint8_t t1) noexcept {
    if (detail_ == Detail::Owned) return *this;
    detail_ = d;
    small_ = std::uint16_t(t0 | (t1 << 8));
    return *this;
  }
  // A moved-from Status keeps its code with an empty static message.
  void dropOwned() noexcept {
    detail_ = Detail::None;
    text_ = "";
  }
  void retain() const noexcept;
  void release() noexcept;

  Detail detail_ = Detail::None;
  std::uint16_t small_ = 0;     // Iterations: the count; Type/TypePair: the GeometryType bytes; CustomName: the issue
  Number number_ = {0};         // Index: the index; Length, Norm, Iterations: the value
  const char* text_ = nullptr;  // the message; CustomName: the shape's name
};

static_assert(sizeof(Status) <= 16, "a Status is a code, a detail of 7 bytes and one pointer");

}  // namespace gq
