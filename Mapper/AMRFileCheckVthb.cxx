// The .vthb check: the XML parses (VTK's expat-based parser, its messages captured), each block
// file exists and parses, and for appended raw data the file covers every array's declared
// offset, header and bytes (compressed or not), with the byte counts the extents imply.
#include "AMRFileChecks.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

namespace amrdm_filecheck
{
namespace
{
void keepMessage(vtkObject*, unsigned long, void* clientData, void* callData)
{
  std::string& out = *static_cast<std::string*>(clientData);
  if (out.empty() && callData)
  {
    out = static_cast<const char*>(callData);
    const std::size_t nl = out.find_first_of("\r\n");
    if (nl != std::string::npos)
      out.resize(nl);
  }
}

/// Parses `path` as VTK XML; returns the root (kept alive by `parser`) or null with `error`.
vtkXMLDataElement* parse(const std::string& path,
  vtkXMLDataParser* parser,
  std::ifstream& in,
  std::string& error)
{
  in.open(path, std::ios::binary);
  if (!in)
  {
    error = Quote(path) + " is missing or unreadable";
    return nullptr;
  }
  std::string message;
  vtkNew<vtkCallbackCommand> keep;
  keep->SetCallback(keepMessage);
  keep->SetClientData(&message);
  parser->AddObserver(vtkCommand::ErrorEvent, keep);
  parser->AddObserver(vtkCommand::WarningEvent, keep);
  parser->SetStream(&in);
  if (!parser->Parse() || !parser->GetRootElement())
  {
    const std::size_t colon = message.find("Error parsing XML");
    error = Quote(path) + " is not well-formed XML" +
            (colon != std::string::npos ? " (" + message.substr(colon) + ")" : std::string()) +
            " (truncated or damaged)";
    return nullptr;
  }
  return parser->GetRootElement();
}

int typeSize(const char* type)
{
  const std::string t = type ? type : "";
  if (t == "Int8" || t == "UInt8" || t == "Char")
    return 1;
  if (t == "Int16" || t == "UInt16")
    return 2;
  if (t == "Int32" || t == "UInt32" || t == "Float32")
    return 4;
  if (t == "Int64" || t == "UInt64" || t == "Float64" || t == "IdType")
    return 8;
  return 0;
}

/// One appended raw array at `at`: its header (n bytes, or a compressed block table) and data.
std::string checkRawArray(const std::string& file,
  std::uint64_t size,
  std::uint64_t at,
  int hs,
  bool compressed,
  bool swap,
  std::uint64_t expected,
  const std::string& name)
{
  auto word = [&](std::uint64_t pos, std::uint64_t& v)
  {
    std::string b;
    if (!ReadBytes(file, pos, std::size_t(hs), b) || b.size() != std::size_t(hs))
      return false;
    v = 0;
    for (int i = 0; i < hs; ++i)
      v = (v << 8) | static_cast<unsigned char>(b[std::size_t(swap ? i : hs - 1 - i)]);
    return true;
  };
  const std::string where = Quote(file) + ": array '" + name + "' at offset " + std::to_string(at);
  std::uint64_t first = 0;
  if (!word(at, first))
    return where + " lies past the end of the file (" + std::to_string(size) + " bytes): truncated";
  std::uint64_t bytes = first, end = at + std::uint64_t(hs) + first;
  if (compressed)
  {
    std::uint64_t blockSize = 0, last = 0;
    if (first > (size - at) / std::uint64_t(hs) || !word(at + hs, blockSize) ||
        !word(at + 2 * hs, last))
      return where + ": its compressed-block table does not fit the file: truncated or damaged";
    bytes = first == 0 ? 0 : (first - 1) * blockSize + (last ? last : blockSize);
    std::string table;
    ReadBytes(file, at + 3 * std::uint64_t(hs), std::size_t(first) * std::size_t(hs), table);
    if (table.size() != std::size_t(first) * std::size_t(hs))
      return where + ": its compressed-block table does not fit the file: truncated";
    end = at + (3 + first) * std::uint64_t(hs);
    for (std::uint64_t b = 0; b < first; ++b)
    {
      std::uint64_t v = 0;
      word(at + (3 + b) * std::uint64_t(hs), v);
      end += v;
    }
  }
  if (expected != 0 && bytes != expected)
    return where + " declares " + std::to_string(bytes) + " bytes; its extent and type need " +
           std::to_string(expected) + " (damaged)";
  if (end > size || end < at)
    return where + " needs the file to reach byte " + std::to_string(end) + ", but it has " +
           std::to_string(size) + ": truncated";
  return "";
}

std::string checkBlock(const std::string& file, const int box[6], std::uint64_t& fileSize)
{
  if (!FileSize(file, fileSize))
    return Quote(file) + " is missing (a block file named by the .vthb)";
  vtkNew<vtkXMLDataParser> parser;
  std::ifstream in;
  std::string error;
  vtkXMLDataElement* root = parse(file, parser, in, error);
  if (!root)
    return error;
  const char* type = root->GetAttribute("type");
  vtkXMLDataElement* image = root->FindNestedElementWithName("ImageData");
  vtkXMLDataElement* piece = image ? image->FindNestedElementWithName("Piece") : nullptr;
  int extent[6];
  if (!type || std::string(type) != "ImageData" || !piece ||
      piece->GetVectorAttribute("Extent", 6, extent) != 6)
    return Quote(file) + " is not VTK ImageData with a Piece extent (damaged)";
  double origin[3], spacing[3];
  if (image->GetVectorAttribute("Origin", 3, origin) != 3 ||
      image->GetVectorAttribute("Spacing", 3, spacing) != 3 ||
      !(spacing[0] > 0 && spacing[1] > 0 && spacing[2] > 0))
    return Quote(file) + ": ImageData has no Origin or no positive Spacing (damaged)";
  std::uint64_t points = 1, cells = 1;
  for (int d = 0; d < 3; ++d)
  {
    if (extent[2 * d + 1] < extent[2 * d] || extent[2 * d + 1] - extent[2 * d] > (1 << 20))
      return Quote(file) + ": its extent is empty or larger than 2^20 on axis " + std::to_string(d);
    if (std::max(1, extent[2 * d + 1] - extent[2 * d]) != box[2 * d + 1] - box[2 * d] + 1)
      return Quote(file) + ": its extent has " + std::to_string(extent[2 * d + 1] - extent[2 * d]) +
             " cells on axis " + std::to_string(d) + ", its amr_box in the .vthb " +
             std::to_string(box[2 * d + 1] - box[2 * d] + 1) + "; expected the same (damaged)";
    points *= std::uint64_t(extent[2 * d + 1] - extent[2 * d] + 1);
    cells *= std::uint64_t(std::max(1, extent[2 * d + 1] - extent[2 * d]));
  }
  const char* header = root->GetAttribute("header_type");
  const int hs = header && std::string(header) == "UInt64" ? 8 : 4;
  const char* compressor = root->GetAttribute("compressor");
  const char* order = root->GetAttribute("byte_order");
  const bool swap = order && std::string(order) == "BigEndian";
  vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
  const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
  const bool raw = appended && (!encoding || std::string(encoding) == "raw");
  if (appended && !raw && std::string(encoding) != "base64")
    return Quote(file) + ": AppendedData encoding '" + encoding + "'; expected raw or base64";
  const char* groups[] = { "CellData", "PointData" };
  for (int g = 0; g < 2; ++g)
  {
    vtkXMLDataElement* data = piece->FindNestedElementWithName(groups[g]);
    for (int i = 0; data && i < data->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* array = data->GetNestedElement(i);
      const char* format = array->GetAttribute("format");
      const char* name = array->GetAttribute("Name");
      const std::string what = Quote(file) + ": array " + std::to_string(i) + " of " + groups[g];
      const std::string f = format ? format : "";
      int components = 1;
      if (std::string(array->GetName()) != "DataArray" || !name ||
          typeSize(array->GetAttribute("type")) == 0 ||
          (array->GetAttribute("NumberOfComponents") &&
            (!array->GetScalarAttribute("NumberOfComponents", components) || components < 1 ||
              components > 1 << 16)) ||
          (f != "appended" && f != "binary" && f != "ascii"))
        return what + " is not a <DataArray> with a Name, a known type, 1..65536 components and "
                      "format appended, binary or ascii (damaged)";
      if (f != "appended")
        continue;
      vtkTypeInt64 offset = -1;
      if (!appended || !array->GetScalarAttribute("offset", offset) || offset < 0 || components < 1)
        return Quote(file) + ": array '" + (name ? name : "?") +
               "' is appended but has no AppendedData section or a valid offset (damaged)";
      if (!raw)
        continue;
      const std::uint64_t tuples = g == 0 ? cells : points;
      const std::uint64_t expected =
        tuples * std::uint64_t(components) * std::uint64_t(typeSize(array->GetAttribute("type")));
      error = checkRawArray(file,
        fileSize,
        std::uint64_t(parser->GetAppendedDataPosition()) + std::uint64_t(offset),
        hs,
        compressor && *compressor,
        swap,
        expected,
        name ? name : "?");
      if (!error.empty())
        return error;
    }
  }
  return "";
}
}

Result CheckVthb(const std::string& path)
{
  Result r;
  r.Format = "vthb";
  vtkNew<vtkXMLDataParser> parser;
  std::ifstream in;
  vtkXMLDataElement* root = parse(path, parser, in, r.Error);
  if (!root)
    return r;
  const char* type = root->GetAttribute("type");
  vtkXMLDataElement* amr = type ? root->FindNestedElementWithName(type) : nullptr;
  if (!amr || std::string(root->GetName()) != "VTKFile")
    return r.Error = Quote(path) + " is not a VTK XML AMR file (expected <VTKFile type=" +
                     "\"vtkOverlappingAMR\"> and a <vtkOverlappingAMR> element)",
           r;
  double origin[3], spacing[3];
  const char* description = amr->GetAttribute("grid_description");
  const std::string known[] = { "XYZ", "XY", "YZ", "XZ", "X", "Y", "Z", "Singleton" };
  if (amr->GetVectorAttribute("origin", 3, origin) != 3 || !description ||
      std::find(std::begin(known), std::end(known), std::string(description)) == std::end(known))
    return r.Error = Quote(path) + ": <" + type + "> has no 3-number origin or no known " +
                     "grid_description (damaged)",
           r;
  std::vector<int> seenLevels;
  for (int b = 0; b < amr->GetNumberOfNestedElements(); ++b)
  {
    vtkXMLDataElement* block = amr->GetNestedElement(b);
    int level = -1;
    if (std::string(block->GetName()) != "Block" || !block->GetScalarAttribute("level", level) ||
        level < 0 || level > 63 || block->GetVectorAttribute("spacing", 3, spacing) != 3 ||
        !(spacing[0] > 0 && spacing[1] > 0 && spacing[2] > 0) ||
        std::find(seenLevels.begin(), seenLevels.end(), level) != seenLevels.end())
      return r.Error =
               Quote(path) + ": element " + std::to_string(b) +
               " is not a <Block level=\"0..63\" spacing=\"3 positive numbers\"> of a level " +
               "not seen before (damaged)",
             r;
    seenLevels.push_back(level);
    if (static_cast<int>(r.BlocksPerLevel.size()) <= level)
      r.BlocksPerLevel.resize(std::size_t(level) + 1, 0);
    for (int i = 0; i < block->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* ds = block->GetNestedElement(i);
      int box[6];
      const char* file = ds->GetAttribute("file");
      int index = -1;
      if (std::string(ds->GetName()) != "DataSet" ||
          ds->GetVectorAttribute("amr_box", 6, box) != 6 || box[1] < box[0] || box[3] < box[2] ||
          box[5] < box[4] || !ds->GetScalarAttribute("index", index) || index != i)
        return r.Error = Quote(path) + ": level " + std::to_string(level) + " entry " +
                         std::to_string(i) + " is not a <DataSet index=\"" + std::to_string(i) +
                         "\" amr_box=\"lo hi lo hi lo hi\"> with lo <= hi (damaged)",
               r;
      if (!file || !*file)
      { // an empty block: the reader gives none either; counted for a warning
        ++r.EmptyBlocks;
        r.EmptyCells += static_cast<long long>(box[1] - box[0] + 1) * (box[3] - box[2] + 1) *
                        (box[5] - box[4] + 1);
        continue;
      }
      const std::string name = file[0] == '/' ? file : Directory(path) + "/" + file;
      std::uint64_t size = 0;
      if (!(r.Error = checkBlock(name, box, size)).empty())
        return r;
      ++r.BlocksPerLevel[std::size_t(level)];
      r.DataBytes += size;
      long long cells = 1;
      for (int d = 0; d < 3; ++d)
        cells *= std::max(0, box[2 * d + 1] - box[2 * d] + 1);
      r.Cells += cells;
    }
  }
  if (r.BlocksPerLevel.empty())
    r.Error = Quote(path) + " describes no blocks; expected at least one <Block> with a <DataSet>";
  return r;
}
}
