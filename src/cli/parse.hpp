#pragma once
// Parses a sub-command's arguments with CLI11 and turns its errors into zcube's conventions.
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "util/error.hpp"

namespace zc::cli {

// Returns -1 when parsing succeeded and the command should run, else the exit status to return
// (0 after --help). Usage errors throw UsageError (exit status 2).
inline int parse(CLI::App& app, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end()); // CLI11 consumes a vector from the back
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    throw UsageError(app.get_name() + ": " + e.what());
  }
  // An empty value is a mistake (an unset shell variable), not "flag not given"; a number is
  // finite (CLI11's ranges let NaN through: every comparison with it is false).
  for (const CLI::Option* o : app.get_options())
    if (o->count() > 0 && o->get_items_expected_min() > 0)
      for (const auto& r : o->results()) {
        if (r.empty())
          throw UsageError(o->get_name() + " '': an empty value (leave the flag out for its "
                                           "default)");
        if (o->get_type_name().starts_with("FLOAT") &&
            !std::isfinite(std::strtod(r.c_str(), nullptr)))
          throw UsageError(o->get_name() + " '" + r + "': expected a finite number");
      }
  return -1;
}

} // namespace zc::cli
