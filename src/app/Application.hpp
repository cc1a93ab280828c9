#pragma once

namespace peridot {

// The `peridot` command: `peridot DECK`, `--help`, `--version`, `--help-model NAME`,
// `--list-models`. Returns the process exit status.
int runApplication(int argc, char** argv);

}  // namespace peridot
