#include "CommandLineParser.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <memory>
#include <stdexcept>
#include <utility>

namespace amrdm_app
{
namespace cli
{
namespace
{
/// A bad value, already one line naming the option.
struct ValueError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// CLI11's layout with the rows' own placeholders ("--size W H") and our usage lines.
class RowFormatter : public CLI::Formatter
{
public:
  explicit RowFormatter(std::string usage)
    : Usage(std::move(usage))
  {
    this->column_width(27);
    this->label("Options", "options");
  }
  std::string make_usage(const CLI::App*, std::string) const override { return this->Usage; }
  std::string make_option_opts(const CLI::Option* opt) const override
  {
    return opt->get_type_name().empty() ? std::string() : " " + opt->get_type_name();
  }

private:
  std::string Usage;
};

std::string joined(const Values& v)
{
  std::string s;
  for (const std::string& x : v)
    s += (s.empty() ? "" : " ") + x;
  return s;
}

/// An app with one CLI11 option per row (no built-in --help: "-h,--help" is a row).
std::unique_ptr<CLI::App> makeApp(const std::vector<Option>& rows, const std::string& usage)
{
  auto app = std::make_unique<CLI::App>("", "amrdm-render");
  app->set_help_flag();
  app->allow_extras();
  app->formatter(std::make_shared<RowFormatter>(usage));
  for (const Option& row : rows)
  {
    if (row.metavars.empty())
    {
      app
        ->add_flag_callback(
          row.name,
          [row]
          {
            std::string unused;
            row.apply({}, unused);
          },
          row.help)
        ->trigger_on_parse();
      continue;
    }
    app
      ->add_option(
        row.name,
        [row](const CLI::results_t& values)
        {
          std::string why;
          if (!row.apply(values, why))
            throw ValueError(row.name + ": " + why);
          return true;
        },
        row.help)
      ->expected(static_cast<int>(row.metavars.size()))
      ->type_name(joined(row.metavars))
      ->trigger_on_parse();
  }
  return app;
}
}

bool parse(const std::vector<Option>& rows,
  int argc,
  char* argv[],
  std::string& positional,
  std::string& error)
{
  std::unique_ptr<CLI::App> app = makeApp(rows, "");
  app->add_option("FILE", positional)->group("");
  try
  {
    app->parse(argc, argv);
  }
  catch (const ValueError& e)
  {
    error = e.what();
    return false;
  }
  catch (const CLI::ArgumentMismatch& e)
  {
    // Too few values at the end of the line: CLI11 says "NAME: N required TYPE missing".
    const std::string what = e.what();
    const std::string name = what.substr(0, what.find(':'));
    for (const Option& row : rows)
    {
      if (row.name == name)
      {
        error = name + ": expected " + joined(row.metavars);
        return false;
      }
    }
    error = what;
    return false;
  }
  catch (const CLI::ParseError& e)
  {
    error = e.what();
    return false;
  }
  for (const std::string& extra : app->remaining())
  {
    const bool looksLikeOption =
      extra.size() > 1 && extra[0] == '-' && !(std::isdigit(extra[1]) || extra[1] == '.');
    if (looksLikeOption)
      error = "unknown option '" + extra + "'";
    else
      error = "more than one input file: '" + positional + "' and '" + extra + "'";
    return false;
  }
  return true;
}

std::string help(const std::vector<Option>& rows, const std::string& usage)
{
  return makeApp(rows, usage)->help();
}

} // namespace cli
} // namespace amrdm_app
