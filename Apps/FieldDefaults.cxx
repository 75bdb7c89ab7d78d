#include "FieldDefaults.h"

#include "mesh/PrepareHierarchy.h"

#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace amrdm_app
{
namespace
{
/// Calls f(grid) for every loaded block.
template<typename F>
void forEachBlock(vtkOverlappingAMR* amr, F&& f)
{
  for (unsigned l = 0; l < amr->GetNumberOfLevels(); ++l)
    for (unsigned i = 0; i < amr->GetNumberOfDataSets(l); ++i)
      if (vtkUniformGrid* g = amr->GetDataSet(l, i))
        f(g);
}

double valueOf(vtkDataArray* a, vtkIdType i, int component)
{
  const int n = a->GetNumberOfComponents();
  if (component >= 0 && component < n)
    return a->GetComponent(i, component);
  if (n == 1)
    return a->GetComponent(i, 0);
  double sum = 0.0;
  for (int c = 0; c < n; ++c)
  {
    const double x = a->GetComponent(i, c);
    sum += x * x;
  }
  return std::sqrt(sum);
}

std::string lower(std::string s)
{
  std::transform(
    s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

/// 0 density, 1 density-like, 2 temperature, 3 anything else.
int nameRank(const std::string& name)
{
  const std::string n = lower(name);
  if (n == "density" || n == "rho" || n == "dens" || n == "gas_density")
    return 0;
  const bool other = n.find("dark") != std::string::npos || n.find("particle") != std::string::npos;
  if (n.find("density") != std::string::npos && !other)
    return 1;
  if (n.rfind("temp", 0) == 0)
    return 2;
  return 3;
}

bool isLeaf(vtkUnsignedCharArray* ghosts, vtkIdType i)
{
  return !ghosts || !(ghosts->GetValue(i) &
                      (vtkDataSetAttributes::REFINEDCELL | vtkDataSetAttributes::HIDDENCELL |
                        vtkDataSetAttributes::DUPLICATECELL));
}

/// The block's array `name` and whether it is point data: a cell array of that name, else a
/// point array (vertex-centred data), else null.
vtkDataArray* fieldArrayOf(vtkUniformGrid* g, const std::string& name, bool& point)
{
  vtkDataArray* a = g->GetCellData()->GetArray(name.c_str());
  point = !a;
  return a ? a : g->GetPointData()->GetArray(name.c_str());
}

vtkUnsignedCharArray* ghostsOf(vtkUniformGrid* g)
{
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    g->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  return ghosts && ghosts->GetNumberOfTuples() == g->GetNumberOfCells() ? ghosts : nullptr;
}

/// The first value, in ascending order of (value, block), at which the volume summed from the
/// smallest value reaches `half`: weighted quickselect (expected linear time; reorders values).
float VolumeWeightedMedian(std::vector<std::pair<float, std::uint32_t>>& values,
  const std::vector<double>& volume,
  double half)
{
  auto first = values.begin(), last = values.end();
  while (last - first > 1)
  {
    const auto mid = first + (last - first) / 2;
    std::nth_element(first, mid, last);
    double left = 0.0; // the volume of [first, mid): every value there sorts before *mid
    for (auto it = first; it != mid; ++it)
      left += volume[it->second];
    if (left >= half)
      last = mid;
    else
    {
      half -= left;
      first = mid;
    }
  }
  return first->first;
}
}

std::vector<CellArrayInfo> ListCellArrays(vtkOverlappingAMR* amr, int component)
{
  std::vector<CellArrayInfo> arrays;
  // Cell arrays first, then point arrays (vertex-centred) whose name no cell array has.
  for (const bool point : { false, true })
    forEachBlock(amr,
      [&](vtkUniformGrid* g)
      {
        vtkDataSetAttributes* cd = point ? static_cast<vtkDataSetAttributes*>(g->GetPointData())
                                         : static_cast<vtkDataSetAttributes*>(g->GetCellData());
        for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
        {
          vtkDataArray* array = cd->GetArray(a);
          const char* name = cd->GetArrayName(a);
          if (!array || !name || std::string(name) == vtkDataSetAttributes::GhostArrayName())
            continue;
          auto it = std::find_if(
            arrays.begin(), arrays.end(), [&](const CellArrayInfo& x) { return x.name == name; });
          if (it != arrays.end() && it->point != point)
            continue; // a cell array of that name wins
          if (it == arrays.end())
          {
            CellArrayInfo info;
            info.name = name;
            info.point = point;
            info.components = array->GetNumberOfComponents();
            info.range[0] = std::numeric_limits<double>::infinity();
            info.range[1] = -std::numeric_limits<double>::infinity();
            arrays.push_back(info);
            it = arrays.end() - 1;
          }
          double r[2];
          const int n = array->GetNumberOfComponents();
          array->GetRange(r, n == 1 ? 0 : (component < n ? component : -1));
          it->range[0] = std::min(it->range[0], r[0]);
          it->range[1] = std::max(it->range[1], r[1]);
        }
      });
  return arrays;
}

std::string DescribeArrays(const std::vector<CellArrayInfo>& arrays)
{
  std::ostringstream s;
  s.precision(4);
  for (std::size_t i = 0; i < arrays.size(); ++i)
  {
    s << (i ? ", '" : "'") << arrays[i].name << "' [" << arrays[i].range[0] << ", "
      << arrays[i].range[1] << "]" << (arrays[i].point ? " (points)" : "");
    if (arrays[i].components > 1)
      s << " (" << arrays[i].components << " components)";
  }
  return arrays.empty() ? std::string("none") : s.str();
}

int ChooseArray(const std::vector<CellArrayInfo>& arrays, std::string& reason)
{
  static const char* rules[] = {
    "the density", "the first density-like array", "the first temperature array", "the first array"
  };
  int best = -1, bestRank = 4;
  for (std::size_t i = 0; i < arrays.size(); ++i)
  {
    const CellArrayInfo& a = arrays[i];
    if (!(std::isfinite(a.range[0]) && std::isfinite(a.range[1]) && a.range[1] > a.range[0]))
      continue;
    const int rank = nameRank(a.name);
    if (rank < bestRank)
    {
      best = int(i);
      bestRank = rank;
    }
  }
  if (best >= 0)
    reason = std::string(rules[bestRank]) + " with a non-constant range";
  return best;
}

bool SummarizeField(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  int logMode,
  FieldSummary& s)
{
  s = FieldSummary();
  // Pass 1: raw leaf values, their block's cell volume, the smallest positive value.
  std::vector<std::pair<float, std::uint32_t>> values; // (value, block)
  std::vector<double> volume;                          // per block: one cell's volume
  double minPositive = std::numeric_limits<double>::infinity();
  double maxValue = -std::numeric_limits<double>::infinity();
  double negativeVolume = 0.0, totalVolume = 0.0;
  forEachBlock(amr,
    [&](vtkUniformGrid* g)
    {
      bool point = false;
      vtkDataArray* a = fieldArrayOf(g, array, point);
      if (!a || a->GetNumberOfTuples() != (point ? g->GetNumberOfPoints() : g->GetNumberOfCells()))
        return;
      double h[3];
      g->GetSpacing(h);
      const auto block = std::uint32_t(volume.size());
      volume.push_back(h[0] * h[1] * h[2]); // point data: each vertex weighs one cell
      vtkUnsignedCharArray* ghosts = point ? nullptr : ghostsOf(g); // vertices: all count
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      {
        if (!isLeaf(ghosts, i))
          continue;
        const double v = valueOf(a, i, component);
        if (!std::isfinite(v) || !std::isfinite(float(v)))
          continue; // beyond float (a damaged file: 1e183): a hole, as in the dual mesh
        values.push_back({ float(v), block });
        totalVolume += volume.back();
        if (v > 0.0)
          minPositive = std::min(minPositive, v);
        else if (v < 0.0)
          negativeVolume += volume.back();
        maxValue = std::max(maxValue, v);
      }
    });
  if (values.empty())
    return false;
  s.leaves = static_cast<long long>(values.size());
  s.decades = maxValue > 0.0 ? std::log10(maxValue / minPositive) : 0.0;
  s.logScale =
    logMode == 1 || (logMode < 0 && s.decades > 3.0 && negativeVolume <= 0.1 * totalVolume);
  if (s.logScale && !(maxValue > 0.0))
    return false; // nothing positive to take the log of
  if (s.logScale)
  {
    s.logFloor = std::floor(std::log10(minPositive)) - 1.0;
    for (auto& v : values)
    {
      s.nonPositive += v.first > 0.0f ? 0 : 1;
      v.first = amrdm::logScaleValue(v.first, s.logFloor); // the one rule, with a floor
    }
  }
  // Selection instead of a sort (a sort of the 6.1M leaves of the single-vortex set was 9 % of
  // an amrdm-render run): min and max in one pass, the 99.9th percentile by nth_element, the
  // volume-weighted median by weighted quickselect. The same values as the sorted order gives.
  const auto range = std::minmax_element(values.begin(), values.end());
  s.min = range.first->first;
  s.max = range.second->first;
  s.volumeHistogram.assign(kHistogramBins, 0.0);
  for (const auto& v : values)
  {
    const double f = s.max > s.min ? (v.first - s.min) / (s.max - s.min) : 0.0;
    const int bin = std::min(kHistogramBins - 1, int(std::max(0.0, f) * kHistogramBins));
    s.volumeHistogram[std::size_t(bin)] += volume[v.second] / totalVolume;
  }
  const std::size_t n = values.size();
  const auto high =
    values.begin() + std::ptrdiff_t(std::min(n - 1, static_cast<std::size_t>(0.999 * double(n))));
  std::nth_element(values.begin(), high, values.end());
  s.high = high->first;
  s.bulk = VolumeWeightedMedian(values, volume, 0.5 * totalVolume);
  return true;
}

std::string AddLogArray(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  const FieldSummary& summary)
{
  const std::string name = "log10(" + array + ")";
  forEachBlock(amr,
    [&](vtkUniformGrid* g)
    {
      bool point = false;
      vtkDataArray* a = fieldArrayOf(g, array, point);
      if (!a)
        return;
      vtkNew<vtkFloatArray> out;
      out->SetName(name.c_str());
      out->SetNumberOfTuples(a->GetNumberOfTuples());
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      {
        const double v = valueOf(a, i, component);
        out->SetValue(i, amrdm::logScaleValue(v, summary.logFloor));
      }
      if (point)
        g->GetPointData()->AddArray(out);
      else
        g->GetCellData()->AddArray(out);
    });
  return name;
}

std::vector<float> BulkOpacityWeights(const FieldSummary& s,
  double lo,
  double hi,
  int n,
  int& damped)
{
  std::vector<double> fraction(std::size_t(n), 0.0);
  const double width = (s.max - s.min) / kHistogramBins;
  for (int b = 0; b < kHistogramBins && width > 0.0; ++b)
  {
    const double centre = s.min + (b + 0.5) * width;
    const double f = (centre - lo) / (hi - lo);
    if (f < 0.0 || f >= 1.0)
      continue;
    fraction[std::size_t(std::min(n - 1, int(f * n)))] += s.volumeHistogram[std::size_t(b)];
  }
  std::vector<float> weights(std::size_t(n), 1.0f);
  damped = 0;
  for (int i = 0; i < n; ++i)
  {
    double smooth = 0.0;
    for (int k = std::max(0, i - 2); k <= std::min(n - 1, i + 2); ++k)
      smooth = std::max(smooth, fraction[std::size_t(k)]);
    if (smooth > kBulkFraction)
      weights[std::size_t(i)] = float(kBulkFraction / smooth);
    damped += weights[std::size_t(i)] < 0.5f;
  }
  return weights;
}

bool VisibleBounds(vtkOverlappingAMR* amr,
  const std::string& array,
  int component,
  const FieldSummary& summary,
  double threshold,
  double bounds[6])
{
  bool any = false;
  forEachBlock(amr,
    [&](vtkUniformGrid* g)
    {
      bool point = false;
      vtkDataArray* a = fieldArrayOf(g, array, point);
      if (!a || a->GetNumberOfTuples() != (point ? g->GetNumberOfPoints() : g->GetNumberOfCells()))
        return;
      int dims[3];
      double origin[3], h[3];
      g->GetDimensions(dims);
      g->GetOrigin(origin);
      g->GetSpacing(h);
      // Point data: tuple i is vertex i, its box the vertex itself.
      const int nx = point ? dims[0] : std::max(1, dims[0] - 1);
      const int ny = point ? dims[1] : std::max(1, dims[1] - 1);
      const double size = point ? 0.0 : 1.0;
      vtkUnsignedCharArray* ghosts = point ? nullptr : ghostsOf(g);
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      {
        if (!isLeaf(ghosts, i))
          continue;
        double v = valueOf(a, i, component);
        if (summary.logScale)
          v = v > 0.0 ? std::log10(v) : summary.logFloor;
        if (!(v > threshold))
          continue;
        const vtkIdType ijk[3] = { i % nx, i / nx % ny, i / (vtkIdType(nx) * ny) };
        for (int d = 0; d < 3; ++d)
        {
          const double c0 = origin[d] + double(ijk[d]) * h[d];
          bounds[2 * d] = any ? std::min(bounds[2 * d], c0) : c0;
          const double c1 = c0 + size * h[d];
          bounds[2 * d + 1] = any ? std::max(bounds[2 * d + 1], c1) : c1;
        }
        any = true;
      }
    });
  return any;
}

void DefaultRange(const FieldSummary& s, double range[2], std::string& how)
{
  range[0] = s.bulk;
  range[1] = s.high;
  how = "from the volume-weighted median (the bulk, transparent) to the 99.9th percentile of the "
        "leaf cells";
  if (!(range[1] > range[0]))
  {
    range[1] = s.max;
    how = "from the volume-weighted median (the bulk, transparent) to the maximum";
  }
  if (!(range[1] > range[0]))
  {
    range[0] = s.min;
    range[1] = s.max > s.min ? s.max : s.min + 1.0;
    how = "the leaf cells' range (the field is nearly constant)";
  }
}
}
