#pragma once
// The tissue and tool of the accuracy commands: --preset FILE (its "tissue" section) and/or
// --youngs-kpa E --poisson NU --tool-radius MM --stiffening-exponent B (these override the preset's
// values; B is the hyperelastic reference's exponential-law b, 0 for neo-Hookean).

#include "app/cli/CommandLine.h"
#include "engine/accuracy/Calibration.h"

#include <string>
#include <vector>

namespace palpate::cli {

/// Defines --preset, --youngs-kpa, --poisson, --tool-radius and --stiffening-exponent on a command.
void addToolContactOptions(CLI::App& command);

struct ToolContactChoice {
    ToolContact contact;
    std::string source;  ///< where E and nu came from (the preset's source, or "command line")
    std::string error;   ///< "" when usable; otherwise names the option or preset key
};

/// Defaults: the phantom-gel values when neither a preset nor values are given.
ToolContactChoice toolContactFromArgs(const Given& args);

}  // namespace palpate::cli
