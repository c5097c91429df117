#include "tools/benchmarks/sweep_report.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace vkw::bench {

std::vector<size_t> pareto_front(const std::vector<SweepRow>& rows) {
    std::vector<size_t> front;
    for (size_t i = 0; i < rows.size(); ++i) {
        const bool dominated = std::any_of(rows.begin(), rows.end(), [&](const SweepRow& other) {
            return other.median_ms <= rows[i].median_ms && other.rel_mse <= rows[i].rel_mse &&
                   (other.median_ms < rows[i].median_ms || other.rel_mse < rows[i].rel_mse);
        });
        if (!dominated) front.push_back(i);
    }
    return front;
}

void write_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows) {
    std::ofstream out(file);
    if (!out) throw UserError("cannot write '" + file.string() + "'");
    out << "setting,median_ms,spread_ms,rel_mse,flip,bias\n";
    for (const SweepRow& row : rows) {
        out << '"' << row.setting << "\"," << row.median_ms << ',' << row.spread_ms << ',' << row.rel_mse << ','
            << row.flip << ',' << row.bias << '\n';
    }
}

namespace {

// One panel: log10 of the metric (y) against log10 of the time (x).
void panel(std::ostringstream& svg, const std::vector<SweepRow>& rows, const std::vector<size_t>& front,
           double (*metric)(const SweepRow&), const char* name, double left, double top, double size) {
    auto log_range = [](std::vector<double> values) {
        for (double& v : values) v = std::log10(std::max(v, 1e-30));
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        const double pad = std::max(0.1, 0.1 * (*hi - *lo));
        return std::pair{*lo - pad, *hi + pad};
    };
    std::vector<double> times, errors;
    for (const SweepRow& row : rows) {
        times.push_back(row.median_ms);
        errors.push_back(std::abs(metric(row)));
    }
    const auto [x0, x1] = log_range(times);
    const auto [y0, y1] = log_range(errors);
    auto x = [&](double v) { return left + (std::log10(std::max(v, 1e-30)) - x0) / (x1 - x0) * size; };
    auto y = [&](double v) { return top + size - (std::log10(std::max(v, 1e-30)) - y0) / (y1 - y0) * size; };
    svg << "<rect x='" << left << "' y='" << top << "' width='" << size << "' height='" << size
        << "' fill='none' stroke='#888'/>\n";
    svg << "<text x='" << left << "' y='" << top - 6 << "' font-size='12'>" << name
        << " (log) against ms per frame (log)</text>\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
        svg << "<circle cx='" << x(times[i]) << "' cy='" << y(errors[i]) << "' r='4' fill='"
            << (on_front ? "#d33" : "#36c") << "'/>\n";
        svg << "<text x='" << x(times[i]) + 6 << "' y='" << y(errors[i]) + 4 << "' font-size='9'>" << rows[i].setting
            << "</text>\n";
    }
}

}  // namespace

void write_svg(const std::filesystem::path& file, const std::string& title, const std::vector<SweepRow>& rows) {
    if (rows.empty()) throw InternalError("write_svg: no rows");
    const std::vector<size_t> front = pareto_front(rows);
    std::ostringstream svg;
    const double size = 260, gap = 90;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << 3 * (size + gap) + 40 << "' height='" << size + 90
        << "' font-family='sans-serif'>\n<text x='20' y='20' font-size='14'>" << title
        << " (red: Pareto front of time and relMSE)</text>\n";
    panel(svg, rows, front, [](const SweepRow& r) { return r.rel_mse; }, "relMSE", 40, 50, size);
    panel(svg, rows, front, [](const SweepRow& r) { return r.flip; }, "FLIP", 40 + size + gap, 50, size);
    panel(svg, rows, front, [](const SweepRow& r) { return r.bias; }, "|bias|", 40 + 2 * (size + gap), 50, size);
    svg << "</svg>\n";
    std::ofstream out(file);
    if (!out) throw UserError("cannot write '" + file.string() + "'");
    out << svg.str();
}

}  // namespace vkw::bench
