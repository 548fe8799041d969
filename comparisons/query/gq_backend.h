#pragma once
// The gq backend: every query through gq's public API (gq/query.h), in the case's precision.
#include "backend.h"
#include "gq_shapes.h"

namespace gq::cases {

class GqBackend final : public Backend {
 public:
  const char* name() const override { return "gq"; }
  Result run(const Case& c, int repeat) override;

 private:
  template <class T> Result runIn(const Case& c, int repeat);
  template <class T> GqShapeFactory<T>& shapes();

  GqShapeFactory<float> floatShapes_;
  GqShapeFactory<double> doubleShapes_;
};

}  // namespace gq::cases
