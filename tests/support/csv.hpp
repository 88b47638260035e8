// SPDX-License-Identifier: MIT
// Reads the CSV files the tools write (history.csv, the material-point driver's output): a
// header line of column names, then rows of numbers.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gsph::test {

inline std::vector<std::vector<double>> readCsv(const std::filesystem::path& path,
                                                std::vector<std::string>& header) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    std::stringstream hs(line);
    for (std::string col; std::getline(hs, col, ',');) header.push_back(col);
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream ls(line);
        for (std::string cell; std::getline(ls, cell, ',');) row.push_back(std::stod(cell));
        rows.push_back(row);
    }
    return rows;
}

}  // namespace gsph::test
