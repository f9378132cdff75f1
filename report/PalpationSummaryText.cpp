#include "report/PalpationSummaryText.h"

#include <QCoreApplication>

namespace palpate {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::PalpationSummaryText)
};
}  // namespace

QStringList palpationSummaryLines(const ScoreReport& report) {
    QStringList lines;
    if (!report.palpation) return lines;
    const PalpationSummary& p = *report.palpation;
    const auto percent = [](const std::optional<double>& v) {
        return v ? QStringLiteral("%1 %").arg(100.0 * *v, 0, 'f', 0) : QStringLiteral("-");
    };
    if (const auto& d = p.detection) {
        const std::size_t lumps = d->hits + d->misses;
        lines << Tr::tr("Lumps found: %1 of %2, false alarms: %3 (sensitivity %4, predictive value %5)")
                     .arg(d->hits)
                     .arg(lumps)
                     .arg(d->falseAlarms)
                     .arg(percent(d->sensitivity), percent(d->positivePredictive));
        if (const auto mm = d->meanLocalisationMm())
            lines << Tr::tr("Findings on a lump lay %1 mm from its centre on average").arg(*mm, 0, 'f', 1);
    }
    lines << Tr::tr("Surface examined at %1 N or more: %2 %")
                 .arg(p.coverage.minForceN, 0, 'f', 1)
                 .arg(100.0 * p.coverageFraction, 0, 'f', 0);
    const ForceByPhase& f = p.forceByPhase;
    if (f.search && f.palpation)
        lines << Tr::tr("Force: searching %1 N, palpating %2 N (medians; %3 times)")
                     .arg(f.search->p50N, 0, 'f', 2)
                     .arg(f.palpation->p50N, 0, 'f', 2)
                     .arg(f.palpationOverSearch.value_or(0.0), 0, 'f', 2);
    for (const PalpationFeedback& fb : p.feedback) lines << QString::fromStdString(fb.text);
    return lines;
}

}  // namespace palpate
