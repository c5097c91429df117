#include "tools/benchmarks/sweep_report.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
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

namespace {

// Text as SVG (XML) character data: a setting may hold any scene value, a title any file name.
std::string xml_text(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            default: out += c;
        }
    }
    return out;
}

// One plotted metric: its title and its value per row (empty: the row has none).
struct Metric {
    std::string name;
    std::function<std::optional<double>(const SweepRow&)> value;
};

// One panel: log10 of |metric| (y) against log10 of the time (x); rows without the metric
// are left out.
void panel(std::ostringstream& svg, const std::vector<SweepRow>& rows, const std::vector<size_t>& front,
           const Metric& metric, double left, double top, double size) {
    std::vector<size_t> shown;
    std::vector<double> times, errors;
    for (size_t i = 0; i < rows.size(); ++i) {
        const std::optional<double> value = metric.value(rows[i]);
        if (!value) continue;
        shown.push_back(i);
        times.push_back(std::log10(std::max(rows[i].median_ms, 1e-30)));
        errors.push_back(std::log10(std::max(std::abs(*value), 1e-30)));
    }
    auto range = [](const std::vector<double>& values) {
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        const double pad = std::max(0.1, 0.1 * (*hi - *lo));
        return std::pair{*lo - pad, *hi + pad};
    };
    svg << "<rect x='" << left << "' y='" << top << "' width='" << size << "' height='" << size
        << "' fill='none' stroke='#888'/>\n";
    svg << "<text x='" << left << "' y='" << top - 6 << "' font-size='12'>" << metric.name << "</text>\n";
    if (shown.empty()) return;
    const auto [x0, x1] = range(times);
    const auto [y0, y1] = range(errors);
    // The axes' ends, so the panel can be read without the CSV.
    svg << "<text x='" << left << "' y='" << top + size + 14 << "' font-size='9'>" << std::pow(10.0, x0)
        << " ms</text><text x='" << left + size << "' y='" << top + size + 14 << "' font-size='9' text-anchor='end'>"
        << std::pow(10.0, x1) << " ms</text>\n";
    svg << "<text x='" << left - 4 << "' y='" << top + size << "' font-size='9' text-anchor='end'>"
        << std::pow(10.0, y0) << "</text><text x='" << left - 4 << "' y='" << top + 9
        << "' font-size='9' text-anchor='end'>" << std::pow(10.0, y1) << "</text>\n";
    for (size_t k = 0; k < shown.size(); ++k) {
        const size_t i = shown[k];
        const double x = left + (times[k] - x0) / (x1 - x0) * size;
        const double y = top + size - (errors[k] - y0) / (y1 - y0) * size;
        const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
        svg << "<circle cx='" << x << "' cy='" << y << "' r='4' fill='" << (on_front ? "#d33" : "#36c") << "'/>\n";
        svg << "<text x='" << x + 5 << "' y='" << y - 3 << "' font-size='9'>" << i + 1 << "</text>\n";
    }
}

}  // namespace

void write_svg(const std::filesystem::path& file, const std::string& title, const std::vector<SweepRow>& rows,
               int downsample_factor) {
    if (rows.empty()) throw InternalError("write_svg: no rows");
    const std::vector<size_t> front = pareto_front(rows);
    std::vector<Metric> metrics{{"relMSE", [](const SweepRow& r) { return std::optional(r.rel_mse); }},
                                {"relMSE, both " + std::to_string(downsample_factor) + "x box-downsampled",
                                 [](const SweepRow& r) { return std::optional(r.rel_mse_downsampled); }},
                                {"FLIP", [](const SweepRow& r) { return std::optional(r.flip); }},
                                {"|bias|", [](const SweepRow& r) { return std::optional(r.bias); }}};
    if (std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.caustic_rel_mse.has_value(); })) {
        metrics.push_back({"relMSE of the caustic layer", [](const SweepRow& r) { return r.caustic_rel_mse; }});
    }
    if (std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.inscatter_rel_mse.has_value(); })) {
        metrics.push_back({"relMSE of the in-scatter layer", [](const SweepRow& r) { return r.inscatter_rel_mse; }});
    }
    const double size = 260, gap = 90;  // panel side and the space between panels, px
    const size_t columns = 3;
    const double rows_of_panels = static_cast<double>((metrics.size() + columns - 1) / columns);
    const double legend_top = 64 + rows_of_panels * (size + gap);
    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << static_cast<double>(columns) * (size + gap) + 40
        << "' height='" << legend_top + 14.0 * static_cast<double>(rows.size()) + 20 << "' font-family='sans-serif'>\n"
        << "<text x='20' y='20' font-size='14'>" << xml_text(title) << "</text>\n"
        << "<text x='20' y='36' font-size='11'>each panel: the error (log) against ms per frame (log); red: the "
           "Pareto front of time and relMSE</text>\n";
    for (size_t m = 0; m < metrics.size(); ++m) {
        const double column = static_cast<double>(m % columns), row = static_cast<double>(m / columns);
        panel(svg, rows, front, metrics[m], 60 + column * (size + gap), 64 + row * (size + gap), size);
    }
    for (size_t i = 0; i < rows.size(); ++i) {
        const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
        svg << "<text x='20' y='" << legend_top + 14.0 * static_cast<double>(i) << "' font-size='11' fill='"
            << (on_front ? "#d33" : "#000") << "'>" << i + 1 << ". " << xml_text(rows[i].setting) << "</text>\n";
    }
    svg << "</svg>\n";
    write_file_checked(file, svg.str());
}

}  // namespace vkw::bench
