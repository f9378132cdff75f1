#pragma once
// What a class server's URL may ask of libpq (docs/results-store.md, "What is protected"): the
// query's options, each checked against the keywords a URL may set and quoted as libpq's conninfo
// quotes a value, so that no value can add another option (a smuggled user= or password=, or a
// later sslmode= that turns off the URL's own). A password is refused in any form; connect_timeout
// has a bound (0 would wait for ever). Qt Core only.

#include <QString>
#include <QUrl>

namespace palpate {

/// The URL's query as Qt's PostgreSQL driver takes it (setConnectOptions: "key='value';..."),
/// with sslmode=prefer and connect_timeout=5 unless the URL sets them; or "" with `error` saying
/// which option and why (never quoting a value: it may hold a secret).
QString serverConnectOptions(const QUrl& url, QString& error);

/// `value` as a libpq conninfo value: in single quotes, a quote or backslash escaped by a backslash.
QString conninfoQuoted(const QString& value);

}  // namespace palpate
