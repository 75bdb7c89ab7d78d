// The option rows of CommandLineValues.h parsed by CLI11 (and their --help printed by CLI11's
// formatter): each row is one CLI11 option with as many values as it has placeholders (a flag
// when none), applied in command-line order as it is parsed. Every problem is one line that
// names the option and what was expected.
#pragma once

#include "CommandLineValues.h"

#include <string>
#include <vector>

namespace amrdm_app
{
namespace cli
{
/// Parses argv against `rows`; the one argument that is no option or value goes to
/// `positional`. False and `error` on the first problem: a bad value ("--spp: expected an
/// integer in [1, 1048576], got '-5'"), too few values ("--size: expected W H"), an unknown
/// option ("unknown option '--bogus'") or a second positional argument.
bool parse(const std::vector<Option>& rows,
  int argc,
  char* argv[],
  std::string& positional,
  std::string& error);

/// The --help text of `rows`: `usage`, then every row with its placeholders and help.
std::string help(const std::vector<Option>& rows, const std::string& usage);

} // namespace cli
} // namespace amrdm_app
