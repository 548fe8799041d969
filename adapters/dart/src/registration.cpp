// Registers the detector in DART's factory under "gq" when the program starts. gq::dart's link options name
// gq_dart_registration (--undefined), so the linker keeps this object file, and with it the registration, in every
// program that links gq::dart, even one that names no gq symbol.
#include "gq/dart/collision_detector.h"

namespace gq {
namespace dart {
namespace {

const ::dart::collision::CollisionDetector::Registrar<CollisionDetector> registrar{
    CollisionDetector::getStaticType(), []() -> std::shared_ptr<::dart::collision::CollisionDetector> {
      return CollisionDetector::create();
    }};

}  // namespace
}  // namespace dart
}  // namespace gq

extern "C" {
// The symbol gq::dart's link options ask the linker for.
const void* gq_dart_registration = &gq::dart::registrar;
}
