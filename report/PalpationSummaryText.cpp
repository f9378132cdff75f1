#include "report/PalpationSummaryText.h"

#include <QCoreApplication>

namespace palpate {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(palpate::PalpationSummaryText)
};
}  // namespace

QString feedbackText(const PalpationFeedback& f, const QLocale& locale) {
    const auto n = [&](std::size_t i, int decimals) {
        return i < f.numbers.size() ? locale.toString(f.numbers[i], 'f', decimals) : QStringLiteral("?");
    };
    const std::size_t count = f.numbers.size();
    if (f.key == "pressed_too_lightly" && count >= 2) {
        QString text = Tr::tr(
                           "Pressed too lightly to reach the deepest lump: it lies %1 mm under the surface, and over "
                           "it the surface sank %2 mm at most.")
                           .arg(n(0, 1), n(1, 1));
        if (count >= 3) text += QLatin1Char(' ') + Tr::tr("Press to about %1 N or more to feel it.").arg(n(2, 1));
        return text;
    }
    // No plural translation is loaded for English: the two forms are spelled out.
    if (f.key == "false_alarms" && count >= 1)
        return f.numbers[0] == 1.0
                   ? Tr::tr("1 finding was on no lump: mark only where the tissue resists more than around it.")
                   : Tr::tr("%1 findings were on no lump: mark only where the tissue resists more than around it.")
                         .arg(locale.toString(f.numbers[0], 'f', 0));
    if (f.key == "low_coverage" && count >= 2)
        return Tr::tr("Examined %1 % of the surface at %2 N or more: cover all of it, in overlapping rows.")
            .arg(n(0, 1), locale.toString(f.numbers[1], 'g', 3));
    if (f.key == "light_palpation" && count >= 2)
        return Tr::tr(
                   "Pressed no harder to palpate than to search (median %1 N against %2 N): press in on a spot "
                   "that feels different.")
            .arg(n(0, 1), n(1, 1));
    return QString::fromStdString(f.text);
}

QStringList palpationSummaryLines(const ScoreReport& report, const QLocale& locale) {
    QStringList lines;
    if (!report.palpation) return lines;
    const PalpationSummary& p = *report.palpation;
    const auto percent = [&locale](const std::optional<double>& v) {
        return v ? QStringLiteral("%1 %").arg(locale.toString(100.0 * *v, 'f', 0)) : QStringLiteral("-");
    };
    if (const auto& d = p.detection) {
        const std::size_t lumps = d->hits + d->misses;
        lines << Tr::tr("Lumps found: %1 of %2, false alarms: %3 (sensitivity %4, predictive value %5)")
                     .arg(d->hits)
                     .arg(lumps)
                     .arg(d->falseAlarms)
                     .arg(percent(d->sensitivity), percent(d->positivePredictive));
        if (const auto mm = d->meanLocalisationMm())
            lines
                << Tr::tr("Findings on a lump lay %1 mm from its centre on average").arg(locale.toString(*mm, 'f', 1));
    }
    lines << Tr::tr("Surface examined at %1 N or more: %2 %")
                 .arg(locale.toString(p.coverage.minForceN, 'g', 3),
                      locale.toString(100.0 * p.coverageFraction, 'f', 0));
    const ForceByPhase& f = p.forceByPhase;
    if (f.search && f.palpation)
        lines << Tr::tr("Force: searching %1 N, palpating %2 N (medians; %3 times)")
                     .arg(locale.toString(f.search->p50N, 'f', 2), locale.toString(f.palpation->p50N, 'f', 2),
                          locale.toString(f.palpationOverSearch.value_or(0.0), 'f', 2));
    for (const PalpationFeedback& fb : p.feedback) lines << feedbackText(fb, locale);
    return lines;
}

}  // namespace palpate
