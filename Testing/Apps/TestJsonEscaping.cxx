// The benchmark's JSON (Benchmarks/BenchResults.h) with names that need escaping: quotes, a
// backslash, control characters (newline, tab, 0x01), UTF-8 and a byte that is not UTF-8 (Latin-1
// e-acute). The hand-written writer this replaced left control characters raw (invalid JSON).
// Every row must parse, give the names back (the invalid byte as U+FFFD), and write ASCII only.
#include "BenchResults.h"

#include <cstdio>
#include <string>
#include <vector>

int main()
{
  const std::string name =
    std::string("a \"quoted\" \\ back\\slash\nnew\tline \x01 caf\xc3\xa9 ") + "latin1-\xe9";
  const std::string expected =
    std::string("a \"quoted\" \\ back\\slash\nnew\tline \x01 caf\xc3\xa9 ") + "latin1-\xef\xbf\xbd";
  int failures = 0;
  auto check = [&](bool ok, const char* what)
  {
    if (!ok)
    {
      std::printf("FAIL: %s\n", what);
      ++failures;
    }
  };

  amrdm_bench::Row row;
  row.set = name;
  row.knob = "knob\"";
  row.setting = "\\";
  row.integrator = "pt";
  row.msPerFrame = 12.5;
  row.frames = 3;
  amrdm_bench::CurvePoint point;
  point.set = name;
  point.spp = 4;
  point.seconds = 0.25;
  const std::string texts[] = { amrdm_bench::toJson(row),
    amrdm_bench::toJson(point),
    amrdm_bench::jsonArray(std::vector<amrdm_bench::Row>{ row, row }) };
  for (const std::string& text : texts)
  {
    bool ascii = true;
    for (unsigned char c : text)
      ascii = ascii && c < 0x80;
    check(ascii, "the JSON is ASCII only");
    nlohmann::json j;
    try
    {
      j = nlohmann::json::parse(text);
    }
    catch (const std::exception& e)
    {
      std::printf("FAIL: does not parse (%s): %s\n", e.what(), text.c_str());
      ++failures;
      continue;
    }
    const nlohmann::json& first = j.is_array() ? j[0] : j;
    check(first["set"] == expected, "the set name comes back (invalid byte as U+FFFD)");
  }
  const nlohmann::json r = nlohmann::json::parse(texts[0], nullptr, false);
  check(!r.is_discarded() && r["knob"] == "knob\"" && r["setting"] == "\\",
    "knob and setting come back");
  check(!r.is_discarded() && r["ms_per_frame"] == 12.5 && r["frames"] == 3, "numbers come back");
  check(!r.is_discarded() && r["rmse"].is_null(), "NaN is written as null");
  check(texts[0].find("\\n") != std::string::npos && texts[0].find("\\u0001") != std::string::npos,
    "control characters are escaped");
  std::printf("%s\n", failures ? "FAILED" : "passed");
  return failures ? 1 : 0;
}
