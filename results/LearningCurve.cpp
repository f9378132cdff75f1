#include "results/LearningCurve.h"

#include <QJsonDocument>
#include <QJsonObject>

namespace palpate {

MetricValues storedMetricValues(const ResultRecord& r) {
    MetricValues out;
    const QJsonObject o = QJsonDocument::fromJson(r.metricsJson.toUtf8()).object();
    for (auto it = o.begin(); it != o.end(); ++it)
        out[it.key().toStdString()] = it.value().isDouble() ? std::optional<double>(it.value().toDouble()) : std::nullopt;
    return out;
}

std::vector<ResultRecord> traineeSessionsOf(const ResultsDatabase& db, qint64 trainee, const QString& path,
                                            const QString& name) {
    std::vector<ResultRecord> out;
    for (ResultRecord& r : db.results(trainee))
        if (!r.expert && isScored(r.outcome) && isSameExercise(r, path, name)) out.push_back(std::move(r));
    return out;
}

ProficiencyStandard expertStandardFor(const ResultsDatabase& db, const Exercise& exercise, const QString& path) {
    std::vector<MetricValues> experts;
    for (const ResultRecord& r : db.expertResults(path, QString::fromStdString(exercise.name)))
        if (isScored(r.outcome)) experts.push_back(storedMetricValues(r));
    return buildProficiencyStandard(exercise, experts);
}

LearningCurve learningCurve(const ResultsDatabase& db, qint64 traineeId, const Exercise& exercise, const QString& path,
                            const QString& title, std::vector<std::string> metrics) {
    LearningCurve c;
    c.sessions = traineeSessionsOf(db, traineeId, path, QString::fromStdString(exercise.name));
    if (c.sessions.empty()) return c;
    c.standard = expertStandardFor(db, exercise, path);
    for (const ResultRecord& r : c.sessions) c.values.push_back(storedMetricValues(r));
    c.progress = judgeSessions(c.standard, c.values);
    if (metrics.empty()) {
        for (const MetricStandard& m : c.standard.metrics)
            if (m.deciding) metrics.push_back(m.metric);
        if (metrics.empty())
            for (const auto& [m, v] : c.values.front()) metrics.push_back(m);
    }
    c.metrics = metrics;
    c.chart.title = title;
    for (const std::string& m : metrics) {
        LearningCurveMetric line;
        line.key = QString::fromStdString(m);
        for (const MetricValues& s : c.values) {
            const auto it = s.find(m);
            line.values.push_back(it == s.end() ? std::nullopt : it->second);
        }
        if (const MetricStandard* st = c.standard.valid() ? c.standard.find(m) : nullptr) {
            line.passMark = st->passMark;
            line.higherIsBetter = st->higherIsBetter;
            line.expertMean = st->mean;
        }
        c.chart.metrics.push_back(line);
    }
    if (c.standard.valid())
        for (const SessionVerdict& s : c.progress.sessions) c.chart.passed.push_back(s.passed);
    if (c.progress.proficientAt) c.chart.proficientAtSession = int(*c.progress.proficientAt) + 1;
    return c;
}

}  // namespace palpate
