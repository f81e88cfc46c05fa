// SPDX-License-Identifier: MIT
#pragma once
/// Cell- and face-centred fields on a MacGrid: flat arrays in the grid's common layout.

#include "fddem/grid/mac_grid.hpp"

#include <array>
#include <span>
#include <vector>

namespace fddem {

/// A scalar array over the grid's storage box (cells or faces of one axis, with ghosts).
template <int Dim>
class GridArray {
public:
    GridArray() = default;
    explicit GridArray(const MacGrid<Dim>& grid, double value = 0.0)
        : strides_(), lo_(grid.storage_lo()), data_(grid.storage_size(), value)
    {
        for (int d = 0; d < Dim; ++d) {
            strides_[static_cast<std::size_t>(d)] = grid.stride(d);
        }
    }

    [[nodiscard]] double& operator[](std::ptrdiff_t offset) noexcept
    {
        return data_[static_cast<std::size_t>(offset)];
    }
    [[nodiscard]] double operator[](std::ptrdiff_t offset) const noexcept
    {
        return data_[static_cast<std::size_t>(offset)];
    }
    [[nodiscard]] double& operator()(const Index<Dim>& i) noexcept { return (*this)[offset(i)]; }
    [[nodiscard]] double operator()(const Index<Dim>& i) const noexcept
    {
        return (*this)[offset(i)];
    }

    [[nodiscard]] double* data() noexcept { return data_.data(); }
    [[nodiscard]] const double* data() const noexcept { return data_.data(); }
    [[nodiscard]] std::span<double> values() noexcept { return data_; }
    [[nodiscard]] std::span<const double> values() const noexcept { return data_; }
    [[nodiscard]] std::size_t size() const noexcept { return data_.size(); }
    void fill(double value) noexcept { std::fill(data_.begin(), data_.end(), value); }

private:
    [[nodiscard]] std::ptrdiff_t offset(const Index<Dim>& i) const noexcept
    {
        std::ptrdiff_t off = 0;
        for (std::size_t d = 0; d < i.size(); ++d) {
            off += static_cast<std::ptrdiff_t>(i[d] - lo_[d]) * strides_[d];
        }
        return off;
    }

    std::array<std::ptrdiff_t, Dim> strides_{};
    Index<Dim> lo_{}; // the storage box's lowest index (MacGrid::storage_lo)
    std::vector<double> data_;
};

/// Cell-centred scalar (pressure, pressure correction, divergence).
template <int Dim>
using CellField = GridArray<Dim>;

/// Face-centred vector: component `axis` lives on the faces normal to `axis`.
template <int Dim>
struct FaceField {
    FaceField() = default;
    explicit FaceField(const MacGrid<Dim>& grid, double value = 0.0)
    {
        for (auto& c : component) {
            c = GridArray<Dim>(grid, value);
        }
    }
    [[nodiscard]] GridArray<Dim>& operator[](int axis) noexcept
    {
        return component[static_cast<std::size_t>(axis)];
    }
    [[nodiscard]] const GridArray<Dim>& operator[](int axis) const noexcept
    {
        return component[static_cast<std::size_t>(axis)];
    }
    void fill(double value) noexcept
    {
        for (auto& c : component) {
            c.fill(value);
        }
    }

    std::array<GridArray<Dim>, Dim> component;
};

} // namespace fddem
