#include "app/cli/ToolContactOptions.h"

#include "engine/scene/TissuePreset.h"

#include <cmath>
#include <cstdlib>

namespace palpate::cli {

void addToolContactOptions(CLI::App& command) {
    // Only whether each is a number is checked here: validateToolContact names what is out of
    // range and why (a tissue the slope-ring cannot render, docs/accuracy.md).
    addValue(command, "preset", "FILE", "a tissue preset: its \"tissue\" section (the options below override it)");
    addValue(command, "youngs-kpa", "E", "Young's modulus, kPa")->check(anyNumber());
    addValue(command, "poisson", "NU", "Poisson's ratio")->check(anyNumber());
    addValue(command, "tool-radius", "MM", "the tool tip's radius, mm")->check(anyNumber());
    addValue(command, "stiffening-exponent", "B",
             "the exponential law's b of the hyperelastic reference, 0 for neo-Hookean")
        ->check(anyNumber());
}

ToolContactChoice toolContactFromArgs(const Given& args) {
    ToolContactChoice c;
    // Gelatin phantom (the shipped phantom_gel preset): soft, nearly incompressible.
    c.contact.material = {4.34e-3, 0.45};
    c.contact.toolRadiusMm = 5.0;
    c.source = "built-in default (phantom gel)";
    if (const auto path = args.option("preset")) {
        const PresetLoadResult loaded = loadTissuePreset(*path);
        if (!loaded.preset) {
            c.error = loaded.error();
            return c;
        }
        if (!loaded.preset->tissue) {
            c.error = *path + ": tissue: missing (the preset has no Young's modulus and Poisson's ratio)";
            return c;
        }
        const TissueProperties& t = *loaded.preset->tissue;
        c.contact.material = {t.youngsModulusKPa * 1e-3, t.poissonRatio};
        c.contact.toolRadiusMm = t.toolRadiusMm;
        c.contact.stiffeningExponent = t.stiffeningExponent;
        c.source = t.source;
    }
    struct Override {
        const char* name;
        double* target;
        double scale;
    };
    const Override overrides[] = {{"youngs-kpa", &c.contact.material.youngsModulusNPerMm2, 1e-3},
                                  {"poisson", &c.contact.material.poissonRatio, 1.0},
                                  {"tool-radius", &c.contact.toolRadiusMm, 1.0},
                                  {"stiffening-exponent", &c.contact.stiffeningExponent, 1.0}};
    for (const Override& o : overrides) {
        if (const auto text = args.option(o.name)) {
            const auto value = parseNumber(*text);
            if (!value) {
                c.error = std::string("--") + o.name + ": '" + *text + "' is not a number";
                return c;
            }
            *o.target = *value * o.scale;
            c.source = "command line";
        }
    }
    if (const std::string e = joinedMessages(validateToolContact(c.contact)); !e.empty()) c.error = e;
    return c;
}

}  // namespace palpate::cli
