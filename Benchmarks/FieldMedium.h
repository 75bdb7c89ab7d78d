// The medium interface of Kernels/sampling/Media.h over one of the benchmark's alternative fields
// (NearestCellField, UniformGrid): the field's value(p, v) through a transfer function, with
// Media.h's fieldRgba/fieldSample, as the kernels' own field media.
#pragma once

#include "sampling/Media.h"

namespace amrdm_bench
{

template<typename Field>
struct FieldMedium
{
  const Field* field = nullptr;
  amrdm::TransferFunctionView tf;

  bool value(const glm::vec3& p, float& v, amrdm::TraceCounters&) const
  {
    return this->field->value(p, v);
  }
  glm::vec4 rgba(const glm::vec3& p, amrdm::TraceCounters& c) const
  {
    return amrdm::fieldRgba(*this, this->tf, p, c);
  }
  amrdm::MediumSample sample(const glm::vec3& p, amrdm::TraceCounters& c) const
  {
    return amrdm::fieldSample(*this, this->tf, p, c);
  }
  float unitDistance() const { return this->tf.unitDistance; }
};

} // namespace amrdm_bench
