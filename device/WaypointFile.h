#pragma once
// A user-supplied tool path for the simulated device (`sim:path:FILE`): a text file with one
// waypoint "t_s x_mm y_mm z_mm" per line, in the scene's frame, played back by linear
// interpolation. The file is user input: every defect is an error naming the file and line, and
// no input crashes the parser (it is fuzzed in tests/device).

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace palpate {

struct Waypoint {
    double timeS = 0.0;
    glm::vec3 positionMm{0.0f};
};

/// Coordinates beyond this are a units mistake (metres for millimetres) or garbage.
inline constexpr double kMaxWaypointCoordinateMm = 1.0e6;

/// Parses waypoint text. Format: fields separated by spaces, tabs or commas; '#' starts a comment;
/// blank lines are skipped; CRLF is accepted; times strictly increase; at least one waypoint.
/// Returns "" or the problem "SOURCE:LINE: problem" (then `out` is empty).
std::string parseWaypoints(std::string_view text, std::string_view sourceName, std::vector<Waypoint>& out);

/// Reads and parses a waypoint file through the bounded reader (base/io/InputFile.h): missing
/// paths, FIFOs, devices, directories, unreadable files and files beyond kWaypointFile's limit
/// (base/io/FileLimits.h) are errors that name the path.
std::string loadWaypointFile(const std::string& path, std::vector<Waypoint>& out);

/// The button presses a waypoint file carries in its comments: "# mark-at T" (Mark) and
/// "# done-at T" (Finish) lines of a scripted trainee, loop times in seconds. The path device has
/// no buttons; the session that plays the file presses them (palpate-cli run --exercise).
struct WaypointButtons {
    std::vector<double> marksS;  ///< in file order
    std::optional<double> doneS;
};

/// Reads those lines: "" or the problem "SOURCE:LINE: problem" (a time that is not a finite number
/// >= 0, a second "# done-at"). Other comments are ignored.
std::string parseWaypointButtons(std::string_view text, std::string_view sourceName, WaypointButtons& out);
/// The same from a file, through the bounded reader.
std::string loadWaypointButtons(const std::string& path, WaypointButtons& out);

}  // namespace palpate
