#include "results/ResultsRoles.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::ResultsRoles)
};

// The class of the role running a statement: a workstation's only (and its policies' subject).
const char* const kOwnClass =
    "(SELECT c.class_name FROM class_workstations c WHERE c.role_name = CAST(current_user AS TEXT))";

QStringList policyStatements() {
    const QString ownClass = QString::fromLatin1(kOwnClass);
    QStringList s;
    // Nobody but the owner and the two roles; nobody but the owner updates or deletes.
    s << QStringLiteral("REVOKE ALL ON palpate_schema, trainees, results, staircases, class_workstations FROM PUBLIC");
    s << QStringLiteral("GRANT SELECT ON palpate_schema, class_workstations TO palpate_workstation, palpate_instructor");
    s << QStringLiteral("GRANT SELECT, INSERT ON trainees, results TO palpate_workstation");
    s << QStringLiteral("GRANT USAGE ON SEQUENCE trainees_id_seq, results_id_seq TO palpate_workstation");
    s << QStringLiteral("GRANT SELECT ON trainees, results TO palpate_instructor");
    for (const char* table : {"trainees", "results", "class_workstations"})
        s << QStringLiteral("ALTER TABLE %1 ENABLE ROW LEVEL SECURITY").arg(QLatin1String(table));
    const auto policy = [&s](const char* name, const char* table, const char* command, const char* role,
                             const QString& clause) {
        s << QStringLiteral("DROP POLICY IF EXISTS %1 ON %2").arg(QLatin1String(name), QLatin1String(table));
        s << QStringLiteral("CREATE POLICY %1 ON %2 FOR %3 TO %4 %5")
                 .arg(QLatin1String(name), QLatin1String(table), QLatin1String(command), QLatin1String(role), clause);
    };
    policy("workstation_reads_itself", "class_workstations", "SELECT", "palpate_workstation",
           QStringLiteral("USING (role_name = CAST(current_user AS TEXT))"));
    policy("instructor_reads_workstations", "class_workstations", "SELECT", "palpate_instructor", QStringLiteral("USING (true)"));
    policy("workstation_reads_its_class", "trainees", "SELECT", "palpate_workstation",
           QStringLiteral("USING (class_name = %1)").arg(ownClass));
    policy("workstation_adds_to_its_class", "trainees", "INSERT", "palpate_workstation",
           QStringLiteral("WITH CHECK (class_name = %1)").arg(ownClass));
    policy("instructor_reads_trainees", "trainees", "SELECT", "palpate_instructor", QStringLiteral("USING (true)"));
    // The trainees a workstation sees are its class's (the policy above applies inside too).
    policy("workstation_reads_its_class", "results", "SELECT", "palpate_workstation",
           QStringLiteral("USING (trainee_id IN (SELECT id FROM trainees))"));
    policy("workstation_sends_its_own", "results", "INSERT", "palpate_workstation",
           QStringLiteral("WITH CHECK (submitted_by = CAST(current_user AS TEXT) AND trainee_id IN (SELECT id FROM trainees))"));
    policy("instructor_reads_results", "results", "SELECT", "palpate_instructor", QStringLiteral("USING (true)"));
    return s;
}

bool needsServer(ResultsDatabase& db, QString* error) {
    if (db.isServer() && db.isOpen()) return true;
    if (error) *error = Tr::tr("%1: roles exist on a PostgreSQL server only, not in an SQLite file").arg(db.path());
    return false;
}

/// The role must be a plain login role the administrator made (with its password), not Palpate:
/// not a built-in (pg_*) or group role, not one that administers the server (superuser, creates
/// roles or databases, replicates, bypasses row security), not the database's owner or the role
/// granting. Its name goes into SQL text: plain names only. "" or why not.
QString roleRefused(ResultsDatabase& db, const QString& role) {
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z_][A-Za-z0-9_.@-]{0,62}$"));
    if (!plain.match(role).hasMatch())
        return Tr::tr("role name \"%1\" is refused: letters, digits, _ . @ - only, starting with a letter or _").arg(role);
    if (role.startsWith(QLatin1String("pg_"), Qt::CaseInsensitive) || role == QLatin1String(kWorkstationGroupRole) ||
        role == QLatin1String(kInstructorGroupRole))
        return Tr::tr(
                   "role %1 is refused: it is a built-in or group role, not a workstation's or an instructor's login "
                   "(CREATE ROLE name LOGIN makes one)")
            .arg(role);
    const QString name = db.quotedText(role);
    QStringList check;
    check << QStringLiteral(
                 "DO $$ DECLARE r pg_roles%ROWTYPE; BEGIN"
                 " SELECT * INTO r FROM pg_roles WHERE rolname = %1;"
                 " IF NOT FOUND THEN RAISE EXCEPTION 'no role %2 on this server (CREATE ROLE ... LOGIN first)'; END IF;"
                 " IF NOT r.rolcanlogin THEN RAISE EXCEPTION 'role %2 is refused: it cannot log in (a group role?);"
                 " a workstation or an instructor is a login role (CREATE ROLE %2 LOGIN)'; END IF;"
                 " IF r.rolsuper OR r.rolcreaterole OR r.rolcreatedb OR r.rolreplication OR r.rolbypassrls THEN"
                 " RAISE EXCEPTION 'role %2 is refused: it administers the server (superuser, creates roles or"
                 " databases, replicates or bypasses row security); give the workstation or instructor a plain"
                 " login role'; END IF;"
                 " IF r.rolname = current_user OR r.oid = (SELECT datdba FROM pg_database WHERE datname ="
                 " current_database()) THEN RAISE EXCEPTION 'role %2 is refused: it owns the results database or"
                 " is the role granting; give the workstation or instructor a login role of its own'; END IF;"
                 " END $$")
                 .arg(name, role);
    QString error;
    return db.runStatements(check, &error) ? QString() : error;
}

/// The server's notices ("policy ... does not exist, skipping", "role is not a member") are not
/// news to the administrator: only errors are reported.
const QString kQuiet = QStringLiteral("SET LOCAL client_min_messages = error");

}  // namespace

bool secureResultsServer(ResultsDatabase& server, QString* error) {
    if (!needsServer(server, error)) return false;
    QStringList s{kQuiet};
    for (const char* role : {kWorkstationGroupRole, kInstructorGroupRole})
        s << QStringLiteral("DO $$ BEGIN IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = '%1') THEN"
                            " CREATE ROLE %1 NOLOGIN; END IF; END $$")
                 .arg(QLatin1String(role));
    s << policyStatements();
    return server.runStatements(s, error);
}

namespace {

/// Before a role's kind changes: a server, a role it has, and the group roles and policies in place.
bool readyToChange(ResultsDatabase& server, const QString& role, QString* error) {
    if (!needsServer(server, error)) return false;
    if (const QString refused = roleRefused(server, role); !refused.isEmpty()) {
        if (error) *error = refused;
        return false;
    }
    return secureResultsServer(server, error);
}

}  // namespace

bool grantWorkstation(ResultsDatabase& server, const QString& role, const QString& className, QString* error) {
    if (!needsServer(server, error)) return false;
    if (className.trimmed().isEmpty()) {
        if (error) *error = Tr::tr("a workstation needs a class (--class NAME)");
        return false;
    }
    if (!readyToChange(server, role, error)) return false;
    const QString r = server.quotedIdentifier(role);
    // One kind of role each: a workstation is not also an instructor.
    return server.runStatements(
        {kQuiet, QStringLiteral("REVOKE palpate_instructor FROM %1").arg(r), QStringLiteral("GRANT palpate_workstation TO %1").arg(r),
         QStringLiteral("INSERT INTO class_workstations (role_name, class_name) VALUES (%1, %2)"
                        " ON CONFLICT (role_name) DO UPDATE SET class_name = excluded.class_name")
             .arg(server.quotedText(role), server.quotedText(className.trimmed()))},
        error);
}

bool grantInstructor(ResultsDatabase& server, const QString& role, QString* error) {
    if (!readyToChange(server, role, error)) return false;
    const QString r = server.quotedIdentifier(role);
    return server.runStatements({kQuiet, QStringLiteral("REVOKE palpate_workstation FROM %1").arg(r),
                                 QStringLiteral("DELETE FROM class_workstations WHERE role_name = %1").arg(server.quotedText(role)),
                                 QStringLiteral("GRANT palpate_instructor TO %1").arg(r)},
                                error);
}

bool revokeRole(ResultsDatabase& server, const QString& role, QString* error) {
    if (!readyToChange(server, role, error)) return false;
    const QString r = server.quotedIdentifier(role);
    return server.runStatements({kQuiet, QStringLiteral("REVOKE palpate_workstation FROM %1").arg(r),
                                 QStringLiteral("REVOKE palpate_instructor FROM %1").arg(r),
                                 QStringLiteral("DELETE FROM class_workstations WHERE role_name = %1").arg(server.quotedText(role))},
                                error);
}

}  // namespace palpate
