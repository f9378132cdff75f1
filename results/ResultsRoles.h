#pragma once
// Who may do what on a class's server (docs/results-store.md, "Roles"). Two group roles:
// palpate_workstation may add trainees to its own class, insert results it sends itself and read
// its class; palpate_instructor reads every class. Row-level security on the tables enforces it,
// so a workstation's program cannot be talked into more. The login roles themselves (and their
// passwords) are the server administrator's: these calls only make them members and say which
// class a workstation belongs to. All of them run as the tables' owner (who bypasses the policies)
// with the right to create roles, and are idempotent.

#include "results/ResultsDatabase.h"

#include <QString>

namespace palpate {

inline constexpr const char* kWorkstationGroupRole = "palpate_workstation";
inline constexpr const char* kInstructorGroupRole = "palpate_instructor";

/// Creates the two group roles when missing, and (again) the grants and the policies.
bool secureResultsServer(ResultsDatabase& server, QString* error = nullptr);
/// Makes the login role `role` a workstation of `className` (moving it from any other class).
bool grantWorkstation(ResultsDatabase& server, const QString& role, const QString& className, QString* error = nullptr);
/// Makes the login role `role` an instructor: reads everything, writes nothing.
bool grantInstructor(ResultsDatabase& server, const QString& role, QString* error = nullptr);
/// Takes both kinds from `role` (a machine retired, a password leaked): it reads and sends nothing
/// more. What it sent stays.
bool revokeRole(ResultsDatabase& server, const QString& role, QString* error = nullptr);

}  // namespace palpate
