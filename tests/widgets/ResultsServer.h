#pragma once
// What the results-store tests share: the PostgreSQL server pg_virtualenv started (PGHOST,
// PGPORT, PGUSER, PGPASSWORD, PGDATABASE; one for every test of the run) and workstations' files.

#include "engine/exercise/ScoreReport.h"

#include <QSqlDatabase>
#include <QTemporaryDir>
#include <QString>
#include <QStringList>

#include <gtest/gtest.h>

namespace palpate::test {

/// The server as a URL without its password (libpq reads PGPASSWORD); "" without a server.
/// `user`: log in as that role instead of PGUSER.
QString serverUrl(const QString& user = {});

#define REQUIRE_SERVER()                                                                                         \
    if (::palpate::test::serverUrl().isEmpty()) GTEST_SKIP() << "no PostgreSQL server (run under pg_virtualenv)"; \
    static_assert(true)

/// Runs statements as PGUSER (the cluster's superuser) on a connection of its own; the first
/// failure's message, or "".
QString runAsAdmin(const QStringList& statements);
/// A completed session of "Press two targets" scoring `score`.
ScoreReport completedReport(double score);
/// A workstation's SQLite file `name`.sqlite in `dir` with `count` results of `trainee`, scoring
/// firstScore, firstScore + 1, ...
QString workstationFile(const QTemporaryDir& dir, const QString& name, const QString& trainee, int count, double firstScore);

/// Empties the server's tables between tests (making them first when the server is new).
void clearServer();

}  // namespace palpate::test
