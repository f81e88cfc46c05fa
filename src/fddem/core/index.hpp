// SPDX-License-Identifier: MIT
#pragma once
/// Typed integer indices and boxes of cells or faces (STYLE.md §4).

#include <array>
#include <cstddef>

namespace fddem {

/// A cell (or face) index, one int per axis.
template <int Dim>
using Index = std::array<int, Dim>;

/// The unit index along `axis`.
template <int Dim>
[[nodiscard]] constexpr Index<Dim> unit(int axis) noexcept
{
    Index<Dim> e{};
    e[static_cast<std::size_t>(axis)] = 1;
    return e;
}

// Templated on std::size_t so that the array size deduces (Index<Dim> is std::array<int, Dim>).
template <std::size_t N>
[[nodiscard]] constexpr std::array<int, N> operator+(std::array<int, N> a,
                                                     const std::array<int, N>& b) noexcept
{
    for (std::size_t d = 0; d < a.size(); ++d) {
        a[d] += b[d];
    }
    return a;
}

template <std::size_t N>
[[nodiscard]] constexpr std::array<int, N> operator-(std::array<int, N> a,
                                                     const std::array<int, N>& b) noexcept
{
    for (std::size_t d = 0; d < a.size(); ++d) {
        a[d] -= b[d];
    }
    return a;
}

/// `i` with its `axis` entry replaced by `value`.
template <std::size_t N>
[[nodiscard]] constexpr std::array<int, N> with_axis(std::array<int, N> i, int axis,
                                                     int value) noexcept
{
    i[static_cast<std::size_t>(axis)] = value;
    return i;
}

/// A half-open box of indices [lo, hi) along every axis.
template <int Dim>
struct Box {
    Index<Dim> lo{};
    Index<Dim> hi{};

    [[nodiscard]] constexpr int extent(int axis) const noexcept
    {
        return hi[static_cast<std::size_t>(axis)] - lo[static_cast<std::size_t>(axis)];
    }
    [[nodiscard]] constexpr std::size_t size() const noexcept
    {
        std::size_t n = 1;
        for (int d = 0; d < Dim; ++d) {
            n *= static_cast<std::size_t>(extent(d) > 0 ? extent(d) : 0);
        }
        return n;
    }
    [[nodiscard]] constexpr bool contains(const Index<Dim>& i) const noexcept
    {
        for (std::size_t d = 0; d < i.size(); ++d) {
            if (i[d] < lo[d] || i[d] >= hi[d]) {
                return false;
            }
        }
        return true;
    }
    /// The box grown by `n` layers on every side.
    [[nodiscard]] constexpr Box grown(int n) const noexcept
    {
        Box b = *this;
        for (std::size_t d = 0; d < b.lo.size(); ++d) {
            b.lo[d] -= n;
            b.hi[d] += n;
        }
        return b;
    }
};

} // namespace fddem
