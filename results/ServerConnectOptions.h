#pragma once
// What a class server's URL may ask of libpq (docs/results-store.md, "What is protected"): the
// query's options, each checked against the keywords a URL may set and quoted as libpq's conninfo
// quotes a value, so that no value can add another option (a smuggled user= or password=, or a
// later sslmode= that turns off the URL's own). A password is refused in any form; connect_timeout
// has a bound (0 would wait for ever), and so has statement_timeout, Palpate's own option: the
// server cancels a statement that runs longer, and the client gives up on a server that has not
// answered a couple of seconds after that (ServerCallDeadline.h). Qt Core only.

#include <QString>
#include <QUrl>

#include <optional>

namespace palpate {

struct ServerConnectDef {
    /// As Qt's PostgreSQL driver takes them (setConnectOptions: "key='value';..."), with
    /// sslmode=prefer and connect_timeout=5 unless the URL sets them, and the statement timeout.
    QString connectOptions;
    int statementTimeoutS = 5;
    /// How long a call may wait for the server's answer before the client gives up on it.
    int callDeadlineMs() const { return statementTimeoutS * 1000 + 2000; }
};

/// The URL's query as options for the driver; or nothing, with `error` saying which option and why
/// (never quoting a value: it may hold a secret).
std::optional<ServerConnectDef> serverConnectOptions(const QUrl& url, QString& error);

/// `value` as a libpq conninfo value: in single quotes, a quote or backslash escaped by a backslash.
QString conninfoQuoted(const QString& value);

}  // namespace palpate
