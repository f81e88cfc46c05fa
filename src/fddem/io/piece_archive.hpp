// SPDX-License-Identifier: MIT
#pragma once
/// Archives for a state held on a grid split across MPI ranks (issue 15), in pieces. Used with
/// Simulation::save_state and load_state (io/checkpoint_archive.hpp), they let the state's one
/// list of members serve a split run, and a run on any number of ranks read it back, without
/// any rank holding the whole grid (grid/storage_pieces.hpp):
///
/// - PieceWriter writes each grid array as this rank's piece of it (its contributed box, x
///   fastest), and every other value only where `has_shared_values` (rank 0: the ranks hold the
///   same copies of everything that is not a grid array).
/// - PieceReader reads the shared values from the piece that has them and sets each grid array
///   of this rank's block from the pieces whose boxes overlap its storage: every entry of the
///   storage, ghosts included, from the piece that holds it.
///
/// On one process the single piece is the whole storage box: the state is the one-process state.

#include "fddem/grid/box_values.hpp"
#include "fddem/grid/storage_pieces.hpp"
#include "fddem/io/checkpoint_archive.hpp"

#include <fmt/format.h>

#include <array>
#include <cstddef>
#include <functional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace fddem {

namespace detail {
template <class T, int Dim>
inline constexpr bool is_grid_array_v = std::is_same_v<std::remove_cv_t<T>, GridArray<Dim>>;
template <class T, int Dim>
inline constexpr bool is_face_field_v = std::is_same_v<std::remove_cv_t<T>, FaceField<Dim>>;
template <class T, int Dim>
struct is_grid_array_set : std::false_type {
};
template <std::size_t N, int Dim>
struct is_grid_array_set<std::array<GridArray<Dim>, N>, Dim> : std::true_type {
};
/// Calls f(array) for each grid array that `value` is or holds; returns false if it holds none.
template <int Dim, class T, class F>
bool for_each_grid_array(T& value, F&& f)
{
    if constexpr (is_grid_array_v<T, Dim>) {
        f(value);
        return true;
    } else if constexpr (is_face_field_v<T, Dim>) {
        for (int a = 0; a < Dim; ++a) {
            f(value[a]);
        }
        return true;
    } else if constexpr (is_grid_array_set<std::remove_cv_t<T>, Dim>::value) {
        for (auto& array : value) {
            f(array);
        }
        return true;
    } else {
        return false;
    }
}
} // namespace detail

/// Writes this rank's piece of a split state (see the file comment).
template <int Dim>
class PieceWriter {
public:
    static constexpr bool is_reading = false;

    PieceWriter(const MacGrid<Dim>& grid, ArchiveWriter& out, bool has_shared_values)
        : box_(contributed_box(grid)), out_(out), has_shared_values_(has_shared_values)
    {
    }

    template <class T>
    void operator()(std::string_view name, const T& value)
    {
        const bool is_grid = detail::for_each_grid_array<Dim>(
            value, [&](const GridArray<Dim>& array) { out_(name, pack(array, box_)); });
        if (!is_grid && has_shared_values_) {
            out_(name, value);
        }
    }

private:
    Box<Dim> box_;
    ArchiveWriter& out_;
    bool has_shared_values_;
};

/// One more piece of a state as PieceReader reads it: its box, and what reads its next grid
/// array's values by name (one array at a time, so that a piece need not be held whole).
template <int Dim>
struct StatePiece {
    Box<Dim> box;
    std::function<void(std::string_view, std::vector<double>&)> read;
};

/// Reads a state in pieces into this rank's block (see the file comment). `shared` is the first
/// piece's archive, which also holds the shared values, and `shared_box` its box; `others` are
/// the other pieces whose boxes overlap this rank's storage (a piece that does not may be left
/// out). Throws CheckpointError if a piece's size does not fit its box or the pieces leave an
/// entry unset.
template <int Dim>
class PieceReader {
public:
    static constexpr bool is_reading = true;

    PieceReader(const MacGrid<Dim>& grid, ArchiveReader& shared, const Box<Dim>& shared_box,
                std::vector<StatePiece<Dim>> others)
        : grid_(grid), shared_(shared), shared_box_(shared_box), others_(std::move(others))
    {
    }

    template <class T>
    void operator()(std::string_view name, T& value)
    {
        const bool is_grid = detail::for_each_grid_array<Dim>(
            value, [&](GridArray<Dim>& array) { read_array(name, array); });
        if (!is_grid) {
            shared_(name, value);
        }
    }

private:
    void read_array(std::string_view name, GridArray<Dim>& array)
    {
        shared_(name, values_);
        std::size_t taken = take_piece(name, shared_box_, array);
        for (const StatePiece<Dim>& piece : others_) {
            piece.read(name, values_);
            taken += take_piece(name, piece.box, array);
        }
        if (taken != grid_.storage_box().size()) {
            throw CheckpointError(fmt::format("has pieces that set {} of the {} entries of {} on "
                                              "rank {}",
                                              taken, grid_.storage_box().size(), name,
                                              grid_.communicator().rank()));
        }
    }
    /// The entries of values_, a piece of `box`, that this rank's storage holds.
    std::size_t take_piece(std::string_view name, const Box<Dim>& box, GridArray<Dim>& array)
    {
        if (values_.size() != box.size()) {
            throw CheckpointError(fmt::format("has a piece of {} with {} values for a box of {}",
                                              name, values_.size(), box.size()));
        }
        return take_overlap<Dim>(grid_, box, values_, array);
    }

    const MacGrid<Dim>& grid_;
    ArchiveReader& shared_;
    Box<Dim> shared_box_;
    std::vector<StatePiece<Dim>> others_;
    std::vector<double> values_; ///< the piece being read (reused)
};

} // namespace fddem
