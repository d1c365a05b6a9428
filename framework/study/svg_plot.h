#pragma once
// A log-log line plot written as SVG by hand: axes with decade ticks, one polyline a series.

#include <string>
#include <vector>

namespace raylab::study {

struct Series {
    std::string label; // shown in the legend, with the fitted slope when the caller adds it
    std::vector<double> x, y;
    bool linesBetween = true; // false: markers only
};

struct LogLogPlot {
    std::string title, xLabel, yLabel;
    std::vector<Series> series;
};

std::string toSvg(const LogLogPlot& plot);

} // namespace raylab::study
