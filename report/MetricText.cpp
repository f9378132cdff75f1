#include "report/MetricText.h"

#include <QCoreApplication>

namespace palpate {

QString metricNameText(Metric metric) {
    QString name = QCoreApplication::translate(kMetricTextContext, metricRow(metric).name);
    // The rows hold names as they read inside a sentence; a label starts with a capital.
    if (!name.isEmpty()) name[0] = name[0].toUpper();
    return name;
}

QString metricNameText(std::string_view key) {
    if (const std::optional<Metric> metric = parseMetric(key)) return metricNameText(*metric);
    return QString::fromUtf8(key.data(), qsizetype(key.size()));
}

QString metricDescriptionText(Metric metric) {
    return QCoreApplication::translate(kMetricTextContext, metricRow(metric).description);
}

QString localMetricValueText(Metric metric, double value, const QLocale& locale) {
    const MetricShown shown = metricShown(metric, value);
    QString text = locale.toString(shown.number, 'f', shown.decimals);
    // Units are NUL-terminated literals of the rows; words among them ("events") are translated.
    if (!shown.unit.empty()) text += QLatin1Char(' ') + QCoreApplication::translate(kMetricTextContext, shown.unit.data());
    return text;
}

QString workDoneText(double workDone, const QLocale& locale) {
    if (!(workDone < 1.0)) return {};
    return QCoreApplication::translate("palpate::MetricText",
                                       "Work done %1 %: the lines that count mistakes earn that share of their points.")
        .arg(locale.toString(100.0 * workDone, 'f', 0));
}

QString scoreText(double score, const QLocale& locale) { return locale.toString(score, 'f', 1); }

}  // namespace palpate
