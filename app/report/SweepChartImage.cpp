#include "app/report/SweepChartImage.h"

#include "app/report/ChartApplication.h"
#include "app/report/ChartImage.h"
#include "app/report/SpeedAccuracyChart.h"

#include <QApplication>
#include <QVBoxLayout>
#include <QWidget>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace palpate {

bool renderSweepChartPng(const std::vector<SweepPoint>& points, const std::string& path, std::string* error, int widthPx,
                         int heightPx) {
    return renderSweepChartPng(points, std::nullopt, path, error, widthPx, heightPx);
}

bool renderSweepChartPng(const std::vector<SweepPoint>& points, const std::optional<ToolContact>& contact,
                         const std::string& path, std::string* error, int widthPx, int heightPx) {
    auto fail = [&](const std::string& message) {
        if (error) *error = message;
        return false;
    };
    if (const std::string problem = chartImageProblem(widthPx, heightPx, path); !problem.empty()) return fail(problem);
    const ChartApplication application;
    if (!application.problem().empty()) return fail(application.problem());

    {
        // One chart per shape, one above the other (the log tick axis needs the width); the axes span
        // every point, so the two compare directly.
        QWidget canvas;
        canvas.setAutoFillBackground(true);
        canvas.setPalette(QPalette(Qt::white));
        auto* layout = new QVBoxLayout(&canvas);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->setSpacing(0);
        std::vector<GeneratedShape> shapes;
        for (const SweepPoint& p : points)
            if (std::find(shapes.begin(), shapes.end(), p.shape) == shapes.end()) shapes.push_back(p.shape);
        if (shapes.empty()) shapes.push_back(GeneratedShape::Sphere);
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            auto* chart = new SpeedAccuracyChart(&canvas);
            chart->setEmptyHint(QObject::tr("No sweep points to draw"));
            chart->setPoints(points);
            chart->setShape(shapes[i]);
            chart->setToolContact(contact);
            chart->setFrameShape(QFrame::NoFrame);
            chart->setTextScale(std::clamp(widthPx / 1000.0, 1.0, 3.0));
            layout->addWidget(chart, 1);
        }
        if (const std::string problem = renderWidgetPng(canvas, widthPx, heightPx, path); !problem.empty())
            return fail(problem);
    }
    return true;
}

}  // namespace palpate
