#include "report/FeelChartImage.h"

#include "report/ChartApplication.h"
#include "report/ChartImage.h"
#include "report/FeelChart.h"


#include <algorithm>

namespace palpate {

std::string renderFeelChartPng(const std::vector<FeelRow>& rows, const std::string& path, int widthPx, int heightPx) {
    if (const std::string problem = chartImageProblem(widthPx, heightPx, path); !problem.empty()) return problem;
    const ChartApplication application;
    if (!application.problem().empty()) return application.problem();
    FeelChart chart;
    chart.setAttribute(Qt::WA_DontShowOnScreen);  // before the rows: the chart is built for an image
    chart.setFrameShape(QFrame::NoFrame);
    chart.setEmptyHint(QObject::tr("No feel bench rows to draw"));
    chart.setTextScale(std::clamp(widthPx / 1000.0, 1.0, 3.0));
    chart.setRows(rows);
    if (const std::string problem = renderWidgetPng(chart, widthPx, heightPx, path); !problem.empty()) return problem;
    return {};
}

}  // namespace palpate
