#include "tools/benchmarks/sweep_csv.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/file_paths.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vkw::bench {
namespace {

std::string quoted_field(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string header(int downsample_factor) {
    const std::string factor = std::to_string(downsample_factor) + "x";
    return "setting,median_ms,spread_ms,rel_mse,flip,bias,rel_mse_" + factor + ",flip_" + factor +
           ",caustic_rel_mse,inscatter_rel_mse,memory_bytes,calibration_ms,median_cal,spread_cal,device,index,"
           "settings";
}

// The fields of one CSV line; false when a quoted field is not closed.
bool split_fields(const std::string& line, std::vector<std::string>& fields) {
    fields.assign(1, "");
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return !quoted;
}

class RowReader {
public:
    RowReader(const std::filesystem::path& file, size_t line, const std::vector<std::string>& fields,
              const std::vector<std::string>& names)
        : file_(file), line_(line), fields_(fields), names_(names) {}

    double number(size_t column) const {
        const std::string& text = fields_[column];
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value)) {
            fail(column, "is not a finite number");
        }
        return value;
    }
    std::optional<double> optional_number(size_t column) const {
        if (fields_[column] == "n/a") return std::nullopt;
        return number(column);
    }
    uint64_t count(size_t column) const {
        const std::string& text = fields_[column];
        char* end = nullptr;
        errno = 0;
        const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
        if (text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno == ERANGE) {
            fail(column, "is not a whole number");
        }
        return value;
    }
    const std::string& text(size_t column) const { return fields_[column]; }
    [[noreturn]] void fail(size_t column, const std::string& why) const {
        throw UserError(quoted_path(file_) + ": line " + std::to_string(line_) + ", column " + names_[column] + ": '" +
                        fields_[column] + "' " + why);
    }

private:
    const std::filesystem::path& file_;
    size_t line_;
    const std::vector<std::string>& fields_;
    const std::vector<std::string>& names_;
};

}  // namespace

void write_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows, int downsample_factor) {
    std::ostringstream out;
    out << header(downsample_factor) << '\n';
    out.precision(6);
    for (const SweepRow& row : rows) {
        out << quoted_field(row.setting) << ',' << row.median_ms << ',' << row.spread_ms << ',' << row.rel_mse << ','
            << row.flip << ',' << row.bias << ',' << row.rel_mse_downsampled << ',' << row.flip_downsampled << ',';
        for (const std::optional<double>& layer : {row.caustic_rel_mse, row.inscatter_rel_mse}) {
            if (layer) {
                out << *layer;
            } else {
                out << "n/a";
            }
            out << ',';
        }
        const double cal = row.calibration_ms;
        out << row.memory_bytes << ',' << cal << ',' << (cal > 0.0 ? row.median_ms / cal : 0.0) << ','
            << (cal > 0.0 ? row.spread_ms / cal : 0.0) << ',' << quoted_field(row.device) << ',' << row.index << ','
            << row.settings << '\n';
    }
    write_file_checked(file, out.str());
}

SweepTable read_csv(const std::filesystem::path& file) {
    require_readable_file_path(file);
    std::ifstream in(file, std::ios::binary);
    std::string line;
    SweepTable table;
    std::vector<std::string> names;
    // Lines of metadata before the header (`# Measured ... at COMMIT ...`: docs/sweeps/run.sh writes
    // where the figures come from) are read past.
    size_t header_number = 1;
    bool has_header = false;
    while ((has_header = static_cast<bool>(std::getline(in, line))) && line.rfind('#', 0) == 0) ++header_number;
    const std::string header_line = quoted_path(file) + ": line " + std::to_string(header_number);
    if (!has_header || !split_fields(line, names) || names.size() < 7 || names[6].rfind("rel_mse_", 0) != 0) {
        throw UserError(header_line + ": not the header of vkwater bench's sweep.csv (" + header(4) +
                        ", with the downsampling factor in place of 4)");
    }
    table.downsample_factor = std::atoi(names[6].c_str() + std::string("rel_mse_").size());
    if (table.downsample_factor < 1 || line != header(table.downsample_factor)) {
        throw UserError(header_line + ": not the columns of this vkwater's bench (" + header(table.downsample_factor) +
                        "); run the bench again");
    }
    std::vector<std::string> fields;
    for (size_t number = header_number + 1; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        if (!split_fields(line, fields) || fields.size() != names.size()) {
            throw UserError(quoted_path(file) + ": line " + std::to_string(number) + ": " +
                            std::to_string(fields.size()) + " fields where the header has " +
                            std::to_string(names.size()));
        }
        const RowReader row(file, number, fields, names);
        SweepRow read;
        read.setting = row.text(0);
        read.median_ms = row.number(1);
        read.spread_ms = row.number(2);
        read.rel_mse = row.number(3);
        read.flip = row.number(4);
        read.bias = row.number(5);
        read.rel_mse_downsampled = row.number(6);
        read.flip_downsampled = row.number(7);
        read.caustic_rel_mse = row.optional_number(8);
        read.inscatter_rel_mse = row.optional_number(9);
        read.memory_bytes = row.count(10);
        read.calibration_ms = row.number(11);
        if (read.calibration_ms <= 0.0) row.fail(11, "is not above 0");
        // median_cal and spread_cal follow from the others.
        read.device = row.text(14);
        read.index = row.count(15);
        read.settings = row.count(16);
        if (read.index >= read.settings) row.fail(15, "is not below the column settings (" + row.text(16) + ")");
        table.rows.push_back(std::move(read));
    }
    return table;
}

}  // namespace vkw::bench
