// amrdm-render's defaults that show the data: which cell array, log or linear, and the
// transfer-function range, chosen from the values of the leaf cells (see FieldDefaults.cxx).
#ifndef FieldDefaults_h
#define FieldDefaults_h

#include <string>
#include <vector>

class vtkOverlappingAMR;

namespace amrdm_app
{
/// A numeric cell or point array (vtkGhostType excluded) and its range over every block.
struct CellArrayInfo
{
  std::string name;
  bool point = false; ///< point data (vertex-centred, rendered without conversion)
  int components = 1;
  double range[2] = { 0, 0 }; ///< of the selected component (magnitude for -1 on vectors)
};

/// Every numeric cell array of the AMR, in the order of the first block that has it, then the
/// point arrays whose name no cell array has (the summaries below read either).
std::vector<CellArrayInfo> ListCellArrays(vtkOverlappingAMR* amr, int component);

/// "'Density' [6.16e-28, 1.6e-21], 'Temperature' [1, 16700], ..." for messages.
std::string DescribeArrays(const std::vector<CellArrayInfo>& arrays);

/// The array a scientist looks at first: among the arrays with a non-degenerate finite range,
/// the first whose name is density ("density", "rho", "dens", "gas_density", any case), else the
/// first density-like name ("...density..." but not dark matter or particles), else the first
/// temperature ("temp..."), else the first. Returns the index into `arrays` or -1 when no array
/// has a non-degenerate range; `reason` says which rule chose it.
int ChooseArray(const std::vector<CellArrayInfo>& arrays, std::string& reason);

/// Leaf-cell statistics of the selected values, in the scale they are rendered in.
struct FieldSummary
{
  bool logScale = false; ///< values are log10(value); values <= 0 are below `logFloor`
  double logFloor =
    0.0; ///< what cells <= 0 become under log: a decade below the smallest positive value
  long long leaves = 0;        ///< leaf cells counted (all cells when there is no vtkGhostType)
  long long nonPositive = 0;   ///< leaf cells <= 0 (or NaN) under log scale
  double decades = 0.0;        ///< log10(max / smallest positive value), 0 without positive values
  double min = 0.0, max = 0.0; ///< over the leaves, in the rendered scale
  double bulk = 0.0;           ///< volume-weighted median: the value most of the domain holds
  double high = 0.0;           ///< 99.9th percentile by leaf count: a robust maximum
  /// Fraction of the leaves' volume per bin of kHistogramBins equal bins over [min, max].
  std::vector<double> volumeHistogram;
};

constexpr int kHistogramBins = 4096;

/// `logMode`: -1 auto (log10 when the positive values span more than three decades and at most
/// 10 % of the domain's volume is negative), 0 linear, 1 log10. Returns false when the array has
/// no finite value.
bool SummarizeField(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  int logMode,
  FieldSummary& summary);

/// Adds the cell array "log10(NAME)" (float) to every block: log10 of the selected values, with
/// values <= 0 and NaN set to `summary.logFloor` (below any range the defaults choose, so they are
/// transparent rather than holes). Returns the new array's name.
std::string AddLogArray(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  const FieldSummary& summary);

/// Opacity weights for `n` equal bins over [lo, hi] that leave the bulk transparent: a bin whose
/// values fill more than kBulkFraction of the domain's volume (after smoothing over +-2 bins) gets
/// the weight kBulkFraction / fraction, so the one or two values most of the domain holds (the
/// background, both sides of a front) fade and what lies between them shows. `damped` receives
/// the number of bins with weight < 1/2.
std::vector<float> BulkOpacityWeights(const FieldSummary& summary,
  double lo,
  double hi,
  int n,
  int& damped);
constexpr double kBulkFraction = 0.05;
constexpr int kBulkBins = 64; ///< bins over the range for BulkOpacityWeights

/// The world bounds of the leaf cells whose rendered value is above `threshold`. Returns false
/// when there is none.
bool VisibleBounds(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  const FieldSummary& summary,
  double threshold,
  double bounds[6]);

/// The default transfer-function range: from the bulk (transparent) to the robust maximum, or the
/// whole range when those coincide. `how` describes it for the user.
void DefaultRange(const FieldSummary& summary, double range[2], std::string& how);
}

#endif
