#include "results/ServerConnectOptions.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>
#include <QUrlQuery>

#include <array>

namespace palpate {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::ResultsDatabase)
};

/// The libpq keywords a URL may set: transport security, timeouts and the client's name. Who
/// connects (user, password, passfile's password, service), where (host, hostaddr, port, dbname)
/// and server options (options, replication) come from the URL's own parts or not at all.
constexpr std::array<const char*, 20> kAllowed = {"sslmode",
                                                  "sslrootcert",
                                                  "sslcert",
                                                  "sslkey",
                                                  "sslcrl",
                                                  "sslcrldir",
                                                  "sslsni",
                                                  "ssl_min_protocol_version",
                                                  "ssl_max_protocol_version",
                                                  "gssencmode",
                                                  "channel_binding",
                                                  "require_auth",
                                                  "connect_timeout",
                                                  "application_name",
                                                  "target_session_attrs",
                                                  "keepalives",
                                                  "keepalives_idle",
                                                  "keepalives_interval",
                                                  "keepalives_count",
                                                  "tcp_user_timeout"};

constexpr int kMaxConnectTimeoutS = 60;
constexpr int kMaxStatementTimeoutS = 600;

/// A whole number of seconds in [1, max], or nothing.
std::optional<int> seconds(const QString& value, int max) {
    bool ok = false;
    const int s = value.toInt(&ok);
    if (!ok || s < 1 || s > max) return std::nullopt;
    return s;
}

bool allowed(const QString& key) {
    for (const char* k : kAllowed)
        if (key == QLatin1String(k)) return true;
    return false;
}

}  // namespace

QString conninfoQuoted(const QString& value) {
    QString out = QStringLiteral("'");
    for (const QChar c : value) {
        if (c == QLatin1Char('\'') || c == QLatin1Char('\\')) out += QLatin1Char('\\');
        out += c;
    }
    return out + QLatin1Char('\'');
}

std::optional<ServerConnectDef> serverConnectOptions(const QUrl& url, QString& error) {
    ServerConnectDef out;
    QStringList options;
    bool sslmode = false, timeout = false;
    for (const auto& [key, value] : QUrlQuery(url).queryItems(QUrl::FullyDecoded)) {
        // A password anywhere (a key, or inside a value: "prefer password=...") is refused, and
        // never repeated in the message. A value that merely names a password-like path
        // (/etc/passwords/ca.crt) is not one.
        static const QRegularExpression passwordSetting(QStringLiteral("password\\s*="),
                                                        QRegularExpression::CaseInsensitiveOption);
        if (key.contains(QLatin1String("password"), Qt::CaseInsensitive) || value.contains(passwordSetting)) {
            error = Tr::tr(
                "a password in the URL is refused: put it in ~/.pgpass or the file PGPASSFILE names "
                "(docs/results-store.md)");
            return std::nullopt;
        }
        if (key == QLatin1String("statement_timeout")) {
            const std::optional<int> s = seconds(value, kMaxStatementTimeoutS);
            if (!s) {
                error = Tr::tr("statement_timeout must be 1 to %1 seconds").arg(kMaxStatementTimeoutS);
                return std::nullopt;
            }
            out.statementTimeoutS = *s;
            continue;
        }
        if (!allowed(key)) {
            error = Tr::tr(
                        "option '%1' is not accepted in the URL (who connects and where come from the URL's own "
                        "parts; docs/results-store.md lists the options)")
                        .arg(key.left(40));
            return std::nullopt;
        }
        // Qt's driver turns every ';' into a space before libpq reads the string.
        if (value.contains(QLatin1Char(';')) || value.contains(QChar(0))) {
            error = Tr::tr("option '%1' has a value libpq cannot take (a ';' or a NUL)").arg(key);
            return std::nullopt;
        }
        if (key == QLatin1String("connect_timeout") && !seconds(value, kMaxConnectTimeoutS)) {
            error = Tr::tr("connect_timeout must be 1 to %1 seconds (0 would wait for ever)").arg(kMaxConnectTimeoutS);
            return std::nullopt;
        }
        options << key + QLatin1Char('=') + conninfoQuoted(value);
        sslmode |= key == QLatin1String("sslmode");
        timeout |= key == QLatin1String("connect_timeout");
    }
    if (!sslmode) options << QStringLiteral("sslmode='prefer'");
    if (!timeout) options << QStringLiteral("connect_timeout='5'");
    // The server cancels a statement that runs longer (one waiting on a lock, a slow disk).
    options << QStringLiteral("options=") +
                   conninfoQuoted(QStringLiteral("-c statement_timeout=%1").arg(out.statementTimeoutS * 1000));
    out.connectOptions = options.join(QLatin1Char(';'));
    error.clear();
    return out;
}

}  // namespace palpate
