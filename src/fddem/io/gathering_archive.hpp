// SPDX-License-Identifier: MIT
#pragma once
/// Archives for a state held on a grid split across MPI ranks (issue 15). Used with
/// Simulation::save_state and load_state (io/checkpoint_archive.hpp), they let the state's one
/// list of members serve a split run as well:
///
/// - GatheringWriter gathers every grid array onto rank 0 (grid/gather_storage.hpp), where it
///   is written as the same grid's array on one process; every other value is rank 0's (the
///   ranks hold the same copies of everything that is not a grid array). The bytes are then a
///   one-process state: a checkpoint any rank count can continue, or a one-process mirror of
///   the run for the outputs.
/// - BlockReader reads such one-process bytes on every rank and keeps each grid array's block.

#include "fddem/grid/gather_storage.hpp"
#include "fddem/io/checkpoint_archive.hpp"

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

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
} // namespace detail

/// Writes a split state as the one-process state (see the file comment). `out` is written on
/// rank 0 only; `whole` is the same grid on one process.
template <int Dim>
class GatheringWriter {
public:
    static constexpr bool is_reading = false;

    GatheringWriter(const MacGrid<Dim>& grid, const MacGrid<Dim>& whole, ArchiveWriter& out)
        : grid_(grid), whole_(whole), out_(out), is_root_(grid.communicator().rank() == 0)
    {
    }

    template <class T>
    void operator()(std::string_view name, const T& value)
    {
        if constexpr (detail::is_grid_array_v<T, Dim>) {
            GridArray<Dim> gathered = is_root_ ? GridArray<Dim>(whole_) : GridArray<Dim>();
            gather_to_root(grid_, value, gathered);
            write(name, gathered);
        } else if constexpr (detail::is_face_field_v<T, Dim>) {
            FaceField<Dim> gathered;
            for (int a = 0; a < Dim; ++a) {
                if (is_root_) {
                    gathered[a] = GridArray<Dim>(whole_);
                }
                gather_to_root(grid_, value[a], gathered[a]);
            }
            write(name, gathered);
        } else if constexpr (detail::is_grid_array_set<std::remove_cv_t<T>, Dim>::value) {
            std::remove_cv_t<T> gathered;
            for (std::size_t k = 0; k < value.size(); ++k) {
                if (is_root_) {
                    gathered[k] = GridArray<Dim>(whole_);
                }
                gather_to_root(grid_, value[k], gathered[k]);
            }
            write(name, gathered);
        } else {
            write(name, value);
        }
    }

private:
    template <class T>
    void write(std::string_view name, const T& value)
    {
        if (is_root_) {
            out_(name, value);
        }
    }

    const MacGrid<Dim>& grid_;
    const MacGrid<Dim>& whole_;
    ArchiveWriter& out_;
    bool is_root_;
};

/// Reads a one-process state (every rank the same bytes) into a split state: each grid array
/// is read whole and its block kept (grid/gather_storage.hpp, take_block).
template <int Dim>
class BlockReader {
public:
    static constexpr bool is_reading = true;

    BlockReader(const MacGrid<Dim>& grid, const MacGrid<Dim>& whole, ArchiveReader& in)
        : grid_(grid), whole_(whole), in_(in)
    {
    }

    template <class T>
    void operator()(std::string_view name, T& value)
    {
        if constexpr (detail::is_grid_array_v<T, Dim>) {
            GridArray<Dim> read(whole_);
            in_(name, read);
            take_block(grid_, read, value);
        } else if constexpr (detail::is_face_field_v<T, Dim>) {
            FaceField<Dim> read(whole_);
            in_(name, read);
            for (int a = 0; a < Dim; ++a) {
                take_block(grid_, read[a], value[a]);
            }
        } else if constexpr (detail::is_grid_array_set<T, Dim>::value) {
            T read;
            for (auto& array : read) {
                array = GridArray<Dim>(whole_);
            }
            in_(name, read);
            for (std::size_t k = 0; k < value.size(); ++k) {
                take_block(grid_, read[k], value[k]);
            }
        } else {
            in_(name, value);
        }
    }

private:
    const MacGrid<Dim>& grid_;
    const MacGrid<Dim>& whole_;
    ArchiveReader& in_;
};

} // namespace fddem
