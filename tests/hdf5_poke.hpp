#pragma once
// Writes one number into an existing HDF5 dataset, in place, as a damaged disk or a careless
// h5py session would: the tests then check that every reader refuses the file by name.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rodsea {

// Element `index` (row-major over the whole dataset) of `dataset` becomes `value`, converted to
// the dataset's type by HDF5 (NaN and infinities survive in float and double datasets).
template <class T>
void poke_hdf5(const std::string& file, const std::string& dataset, std::uint64_t index, T value) {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    if (f < 0) throw std::runtime_error("poke_hdf5: cannot open " + file);
    const hid_t set = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    if (set < 0) {
        H5Fclose(f);
        throw std::runtime_error("poke_hdf5: no dataset " + dataset + " in " + file);
    }
    const hid_t space = H5Dget_space(set);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), at(dims.size());
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    std::uint64_t rest = index;
    for (int d = rank - 1; d >= 0; --d) {
        at[static_cast<std::size_t>(d)] = rest % dims[static_cast<std::size_t>(d)];
        rest /= dims[static_cast<std::size_t>(d)];
    }
    const hsize_t one = 1;
    H5Sselect_elements(space, H5S_SELECT_SET, 1, at.data());
    const hid_t memory = H5Screate_simple(1, &one, nullptr);
    const hid_t type = std::is_same_v<T, double>         ? H5T_NATIVE_DOUBLE
                       : std::is_same_v<T, float>        ? H5T_NATIVE_FLOAT
                       : std::is_same_v<T, std::int64_t> ? H5T_NATIVE_INT64
                                                         : H5T_NATIVE_INT32;
    const herr_t status = H5Dwrite(set, type, memory, space, H5P_DEFAULT, &value);
    H5Sclose(memory);
    H5Sclose(space);
    H5Dclose(set);
    H5Fclose(f);
    if (status < 0) throw std::runtime_error("poke_hdf5: cannot write " + dataset);
}

// The file offset of the chunk holding element (frame, 0, 0) of a chunked dataset, for flipping
// a byte on disk as a failing sector would.
inline std::uint64_t hdf5_chunk_offset(const std::string& file, const std::string& dataset,
                                       std::uint64_t frame) {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t set = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    const hsize_t at[3] = {frame, 0, 0};
    haddr_t address = 0;
    hsize_t size = 0;
    const herr_t status = H5Dget_chunk_info_by_coord(set, at, nullptr, &address, &size);
    H5Dclose(set);
    H5Fclose(f);
    if (status < 0)
        throw std::runtime_error("hdf5_chunk_offset: no chunk at frame " + std::to_string(frame) +
                                 " of " + dataset);
    return address;
}

// The number of elements of a dataset.
inline std::uint64_t hdf5_elements(const std::string& file, const std::string& dataset) {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t set = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(set);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    H5Dclose(set);
    H5Fclose(f);
    return n < 0 ? 0 : static_cast<std::uint64_t>(n);
}

}  // namespace rodsea
