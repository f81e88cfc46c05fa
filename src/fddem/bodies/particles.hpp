// SPDX-License-Identifier: MIT
#pragma once
/// The body store: every particle of the run, one Particle record each, kept in the order of
/// their ids. Stages iterate over it and index it by position; contact history and checkpoints
/// name a body by its id, so that bodies can enter, leave or (under MPI) migrate without
/// renumbering the others.

#include "fddem/bodies/particle.hpp"
#include "fddem/core/errors.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

namespace fddem {

template <int Dim>
class Particles {
public:
    using value_type = Particle<Dim>;
    using iterator = typename std::vector<Particle<Dim>>::iterator;
    using const_iterator = typename std::vector<Particle<Dim>>::const_iterator;

    [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }
    [[nodiscard]] bool empty() const noexcept { return items_.empty(); }
    [[nodiscard]] iterator begin() noexcept { return items_.begin(); }
    [[nodiscard]] iterator end() noexcept { return items_.end(); }
    [[nodiscard]] const_iterator begin() const noexcept { return items_.begin(); }
    [[nodiscard]] const_iterator end() const noexcept { return items_.end(); }
    [[nodiscard]] Particle<Dim>& operator[](std::size_t k) noexcept { return items_[k]; }
    [[nodiscard]] const Particle<Dim>& operator[](std::size_t k) const noexcept
    {
        return items_[k];
    }
    [[nodiscard]] Particle<Dim>& front() noexcept { return items_.front(); }
    [[nodiscard]] const Particle<Dim>& front() const noexcept { return items_.front(); }
    [[nodiscard]] std::span<Particle<Dim>> all() noexcept { return items_; }
    [[nodiscard]] std::span<const Particle<Dim>> all() const noexcept { return items_; }

    /// Adds a body; its id must be new. The store stays sorted by id.
    void add(Particle<Dim> particle)
    {
        const auto at = lower_bound(particle.id);
        if (at != items_.end() && at->id == particle.id) {
            throw InternalError("Particles::add: id " + std::to_string(particle.id) + " is taken");
        }
        items_.insert(at, std::move(particle));
    }
    /// Removes the body of `id` (one that left the domain, or this rank); false if none.
    bool remove(int id)
    {
        const auto at = lower_bound(id);
        if (at == items_.end() || at->id != id) {
            return false;
        }
        items_.erase(at);
        return true;
    }
    /// The body of `id`, or nullptr.
    [[nodiscard]] const Particle<Dim>* find(int id) const
    {
        const auto at = std::lower_bound(items_.begin(), items_.end(), id,
                                         [](const Particle<Dim>& p, int i) { return p.id < i; });
        return at != items_.end() && at->id == id ? &*at : nullptr;
    }
    [[nodiscard]] bool has_free_body() const
    {
        return std::any_of(items_.begin(), items_.end(),
                           [](const Particle<Dim>& p) { return p.is_free(); });
    }
    /// A body free now or released later (Particle::moves_freely): what collisions need.
    [[nodiscard]] bool has_moving_body() const
    {
        return std::any_of(items_.begin(), items_.end(),
                           [](const Particle<Dim>& p) { return p.moves_freely(); });
    }

private:
    iterator lower_bound(int id)
    {
        return std::lower_bound(items_.begin(), items_.end(), id,
                                [](const Particle<Dim>& p, int i) { return p.id < i; });
    }

    std::vector<Particle<Dim>> items_; ///< ascending ids
};

} // namespace fddem
