// SPDX-License-Identifier: MIT
// Bytewise comparison of two HDF5 files, dataset by dataset (restart tests): every dataset of
// either file must exist in the other with the same shape, the same element type and the same
// bytes (memcmp of the raw values, no tolerance). Variable-length strings are compared as text.
#pragma once

#include <hdf5.h>

#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace gsph::test {

namespace h5compare {

inline herr_t collectDataset(hid_t, const char* name, const H5O_info_t* info, void* data) {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::set<std::string>*>(data)->insert(name);
    return 0;
}

struct Raw {
    std::vector<hsize_t> shape;
    std::string type;  ///< class and size, e.g. "1:8" (H5T_FLOAT, 8 bytes); "string" for text
    std::vector<unsigned char> bytes;
};

inline Raw readRaw(hid_t file, const std::string& name) {
    Raw r;
    const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Dget_type(d);
    const hid_t space = H5Dget_space(d);
    r.shape.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, r.shape.data(), nullptr);
    const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) {
        r.type = "string";
        std::vector<char*> text(count, nullptr);
        if (count > 0) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data());
        for (char* t : text) {
            r.bytes.insert(r.bytes.end(), t, t + (t ? std::strlen(t) : 0));
            r.bytes.push_back(0);
        }
        if (count > 0) H5Dvlen_reclaim(type, space, H5P_DEFAULT, text.data());
    } else {
        r.type = std::to_string(H5Tget_class(type)) + ":" + std::to_string(H5Tget_size(type));
        r.bytes.resize(count * H5Tget_size(type));
        if (count > 0) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, r.bytes.data());
    }
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(d);
    return r;
}

inline std::set<std::string> datasets(hid_t file) {
    std::set<std::string> names;
    H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collectDataset, &names, H5O_INFO_BASIC);
    return names;
}

}  // namespace h5compare

/// Empty if every dataset of the two files is bytewise identical; else what differs. Also sets
/// `compared` to the number of datasets compared.
inline std::string differingDatasets(const std::filesystem::path& a, const std::filesystem::path& b,
                                     int* compared = nullptr) {
    const hid_t fa = H5Fopen(a.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t fb = H5Fopen(b.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (fa < 0 || fb < 0) {
        if (fa >= 0) H5Fclose(fa);
        if (fb >= 0) H5Fclose(fb);
        return "cannot open " + a.string() + " or " + b.string();
    }
    std::string diff;
    const std::set<std::string> na = h5compare::datasets(fa), nb = h5compare::datasets(fb);
    if (na != nb) diff += "different dataset lists; ";
    int n = 0;
    for (const std::string& name : na) {
        if (!nb.count(name)) continue;
        const h5compare::Raw ra = h5compare::readRaw(fa, name), rb = h5compare::readRaw(fb, name);
        ++n;
        if (ra.shape != rb.shape || ra.type != rb.type || ra.bytes != rb.bytes) diff += name + " ";
    }
    H5Fclose(fa);
    H5Fclose(fb);
    if (compared) *compared = n;
    return diff;
}

}  // namespace gsph::test
