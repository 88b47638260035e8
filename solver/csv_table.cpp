// SPDX-License-Identifier: MIT
#include "csv_table.hpp"

#include <cstdio>
#include <stdexcept>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace gsph::solver {

CsvTable::CsvTable(std::filesystem::path path, const std::vector<std::string>& columns)
    : path_(std::move(path)), columns_(columns.size()) {
    for (const std::string& name : columns) {
        if (!header_.empty()) header_.push_back(',');
        header_.append(name);
    }
    header_.push_back('\n');
    text_ = header_;
}

void CsvTable::cell(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    if (cells_++ != 0) text_ += ',';
    text_ += text;
}

void CsvTable::endRow() {
    if (cells_ != columns_)
        throw std::logic_error(path_.filename().string() + ": a row of " + std::to_string(cells_) +
                               " cells for " + std::to_string(columns_) + " columns");
    text_ += '\n';
    cells_ = 0;
}

void CsvTable::restore(const std::string& text, const std::string& source) {
    if (text.compare(0, header_.size(), header_) != 0)
        throw InputError(source + ": its " + path_.filename().string() +
                         " has other columns than this gsph-solve writes");
    text_ = text;
}

void CsvTable::flush() const {
    writeTextAtomically(path_, text_);
}

}  // namespace gsph::solver
