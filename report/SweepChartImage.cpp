#include "report/SweepChartImage.h"

#include "report/ChartApplication.h"
#include "report/ChartImage.h"
#include "report/SpeedAccuracyChart.h"

#include <QApplication>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace palpate {

std::string renderSweepChartPng(const std::vector<SweepPoint>& points, const std::string& path, int widthPx,
                                int heightPx) {
    return renderSweepChartPng(points, std::nullopt, path, widthPx, heightPx);
}

std::string renderSweepChartPng(const std::vector<SweepPoint>& points, const std::optional<ToolContact>& contact,
                                const std::string& path, int widthPx, int heightPx) {
    if (const std::string problem = chartImageProblem(widthPx, heightPx, path); !problem.empty()) return problem;
    const ChartApplication application;
    if (!application.problem().empty()) return application.problem();

    {
        // One chart per shape (and per site of the organ sweep), one above the other (the log tick
        // axis needs the width); the axes span every point, so the charts compare directly.
        QWidget canvas;
        canvas.setAutoFillBackground(true);
        canvas.setPalette(QPalette(Qt::white));
        auto* layout = new QVBoxLayout(&canvas);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(0);
        std::vector<std::pair<GeneratedShape, std::string>> panes;
        for (const SweepPoint& p : points)
            if (std::find(panes.begin(), panes.end(), std::pair{p.shape, p.site}) == panes.end()) panes.emplace_back(p.shape, p.site);
        if (panes.empty()) panes.emplace_back(GeneratedShape::Sphere, std::string());
        for (const auto& [shape, site] : panes) {
            auto* chart = new SpeedAccuracyChart(&canvas);
            chart->setEmptyHint(QObject::tr("No sweep points to draw"));
            chart->setPoints(points);
            chart->setShape(shape);
            chart->setSite(site);
            chart->setToolContact(contact);
            chart->setFrameShape(QFrame::NoFrame);
            chart->setTextScale(std::clamp(widthPx / 1000.0, 1.0, 3.0));
            layout->addWidget(chart, 1);
        }
        if (const std::string problem = renderWidgetPng(canvas, widthPx, heightPx, path); !problem.empty())
            return problem;
    }
    return {};
}

}  // namespace palpate
