// Colour maps and opacity ramps for amrdm-render: named presets or a text file.
#ifndef TransferFunctionPresets_h
#define TransferFunctionPresets_h

#include "sampling/TransferFunction.h" // For amrdm::TransferFunction

#include <string>
#include <vector>

namespace amrdm_app
{
/// Preset names accepted by MakeTransferFunction.
const char* PresetNames();

/// `spec` is a preset name (colour map with a linear opacity ramp from 0 at `lo` to
/// `maxOpacity` at `hi`) or a text file of lines `value r g b a` (values in the field's units,
/// sorted; '#' starts a comment), resampled to 256 entries over its own value range.
/// `opacityWeights` (presets only; empty = none) multiply the ramp entry by entry (any count,
/// resampled to the table). Returns false and sets `error` for an unknown preset or a bad file.
bool MakeTransferFunction(const std::string& spec,
  double lo,
  double hi,
  double maxOpacity,
  double unitDistance,
  amrdm::TransferFunction& tf,
  std::string& error,
  const std::vector<float>& opacityWeights = {});

/// True when `spec` names a preset (not a file).
bool IsPreset(const std::string& spec);
}

#endif
