#pragma once
// Two files of one mesh, one in mm and one in another unit (docs/meshes.md, "Units"), written so
// that both, each read in its own unit, give the same vertices to the bit: the mesh a session in
// either builds is the same, and so are its hash, its forces and its score.

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

namespace palpate::test {

struct UnitMeshFiles {
    std::string mmPath;    ///< coordinates in mm
    std::string unitPath;  ///< the same mesh, coordinates in the other unit
};

/// From an OFF file in mm (vertex numbering kept): `<stem>.mm.off` and `<stem>.<unitName>.off` in
/// `dir`. A coordinate in the unit is the float nearest x / mmPerUnit; the mm file holds what the
/// loader makes of it (the float nearest that times mmPerUnit), each printed with 17 digits so
/// that the reader's double is that float exactly (the loader reads doubles and scales them).
inline UnitMeshFiles writeUnitMeshFiles(const std::string& sourceOff, double mmPerUnit, const std::string& unitName,
                                        const std::string& dir, const std::string& stem) {
    std::ifstream in(sourceOff);
    std::string magic;
    std::size_t vertices = 0, faces = 0, edges = 0;
    if (!(in >> magic >> vertices >> faces >> edges) || magic != "OFF")
        throw std::runtime_error(sourceOff + ": not an OFF file");
    std::ostringstream mm, unit;
    mm << "OFF\n" << vertices << " " << faces << " 0\n";
    unit << "OFF\n" << vertices << " " << faces << " 0\n";
    char text[64];
    for (std::size_t v = 0; v < vertices; ++v) {
        for (int k = 0; k < 3; ++k) {
            double x = 0.0;
            if (!(in >> x)) throw std::runtime_error(sourceOff + ": short vertex list");
            const float inUnit = float(x / mmPerUnit);
            const float inMm = float(double(inUnit) * mmPerUnit);
            std::snprintf(text, sizeof text, "%.17g%s", double(inUnit), k < 2 ? " " : "\n");
            unit << text;
            std::snprintf(text, sizeof text, "%.17g%s", double(inMm), k < 2 ? " " : "\n");
            mm << text;
        }
    }
    in >> std::ws;
    std::string rest((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    mm << rest;
    unit << rest;
    UnitMeshFiles files{dir + "/" + stem + ".mm.off", dir + "/" + stem + "." + unitName + ".off"};
    std::ofstream(files.mmPath) << mm.str();
    std::ofstream(files.unitPath) << unit.str();
    return files;
}

}  // namespace palpate::test
