#pragma once
// Plots written as SVG by hand, for pages that must open offline: a log-log line plot (axes with
// decade ticks, one polyline a series: the studies) and a histogram (the class page's scores).

#include <string>
#include <vector>

namespace raylab {

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

// Counts of values in equal bins from `low` to `high` (the last bin holds `high`); a value outside
// is left out.
struct Histogram {
    std::string title, xLabel, yLabel;
    double low = 0., high = 1.;
    std::vector<int> counts; // a bar each
};

// `values` counted into `bins` equal bins over [low, high].
Histogram histogramOf(std::string title, std::string xLabel, std::string yLabel, const std::vector<double>& values,
                      double low, double high, int bins);

std::string toSvg(const Histogram& histogram);

} // namespace raylab::study
