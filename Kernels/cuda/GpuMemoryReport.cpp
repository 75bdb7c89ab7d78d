// GpuMemoryReport's totals and JSON. See GpuMemoryReport.h.
#include "cuda/GpuMemoryReport.h"

#include <sstream>

namespace amrdm
{
namespace
{
/// `text` as the inside of a JSON string (quotes, backslashes and control characters escaped).
std::string jsonEscaped(const std::string& text)
{
  std::string out;
  for (const char ch : text)
  {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\')
    {
      out += '\\';
      out += ch;
    }
    else if (u < 0x20)
    {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
    else
    {
      out += ch;
    }
  }
  return out;
}
} // namespace

std::uint64_t GpuMemoryReport::computedTotal() const
{
  std::uint64_t t = 0;
  for (const Entry& e : this->entries)
    t += e.computed;
  return t;
}

std::int64_t GpuMemoryReport::measuredTotal() const
{
  std::int64_t t = 0;
  for (const Entry& e : this->entries)
    t += e.measured;
  return t;
}

const GpuMemoryReport::Entry* GpuMemoryReport::find(const std::string& category) const
{
  for (const Entry& e : this->entries)
    if (e.category == category)
      return &e;
  return nullptr;
}

std::string GpuMemoryReport::toJson() const
{
  std::ostringstream s;
  s << "{\"device\": \"" << jsonEscaped(this->deviceName)
    << "\", \"deviceTotalBytes\": " << this->deviceTotal
    << ", \"deviceFreeBytes\": " << this->deviceFree << ", \"categories\": {";
  for (std::size_t i = 0; i < this->entries.size(); ++i)
  {
    s << (i ? ", " : "") << "\"" << this->entries[i].category
      << "\": {\"computed\": " << this->entries[i].computed
      << ", \"measured\": " << this->entries[i].measured << "}";
  }
  s << "}, \"computedTotal\": " << this->computedTotal()
    << ", \"measuredTotal\": " << this->measuredTotal() << "}";
  return s.str();
}

} // namespace amrdm
