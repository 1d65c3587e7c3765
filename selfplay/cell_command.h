// The options of `olympics-league cell` (docs/deploy.md).
#pragma once

#include <CLI/CLI.hpp>

#include "cell_worker.h"

namespace olympics::selfplay {

// Adds the cell's options to `cmd`; `settings` gets their values (and the defaults that depend
// on this host: the cell's name, the policy worker program) when the command line is parsed.
void add_cell_options(CLI::App& cmd, CellSettings& settings);

}  // namespace olympics::selfplay
