// SPDX-License-Identifier: MIT
#include "fddem/coupling/lubrication_coupling.hpp"

#include "fddem/coupling/rigid_update.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <vector>

namespace fddem {
namespace {

/// K_j of a lever l: c_t (|l|² 1 − l lᵀ); c_t |l|² about z in 2D.
template <int Dim>
Inertia<Dim> turning_resistance(const Vec<Dim>& lever, double tangential)
{
    if constexpr (Dim == 2) {
        return tangential * lever.squaredNorm();
    } else {
        return tangential *
               (lever.squaredNorm() * Eigen::Matrix3d::Identity() - lever * lever.transpose());
    }
}

} // namespace

template <int Dim>
Matrix<Dim> gap_resistance(const Vec<Dim>& normal, const LubricationResistance& c)
{
    const Matrix<Dim> along = normal * normal.transpose();
    return c.normal * along + c.tangential * (Matrix<Dim>::Identity() - along);
}

template <int Dim>
Vec<Dim> partner_surface_velocity(const LubricationLink<Dim>& link,
                                  std::span<const Particle<Dim>> bodies)
{
    if (link.partner == LubricationLink<Dim>::wall) {
        return link.wall_velocity;
    }
    const Particle<Dim>& partner = bodies[link.partner];
    return partner.velocity + cross(partner.omega, link.partner_lever);
}

template <int Dim>
LinkedDamping<Dim> linked_damping(std::span<const LubricationLink<Dim>> links,
                                  const Vec<Dim>& velocity, const AngularVec<Dim>& omega,
                                  std::span<const Particle<Dim>> bodies)
{
    LinkedDamping<Dim> d;
    for (const LubricationLink<Dim>& link : links) {
        const Matrix<Dim> c = gap_resistance<Dim>(link.normal, link.resistance);
        const Vec<Dim> surface = partner_surface_velocity<Dim>(link, bodies);
        d.force_rate += c;
        d.force_target += c * Vec<Dim>(surface - cross(omega, link.lever));
        d.moment_rate += turning_resistance<Dim>(link.lever, link.resistance.tangential);
        d.moment_target += cross(link.lever, Vec<Dim>(c * Vec<Dim>(surface - velocity)));
    }
    return d;
}

template <int Dim>
LinkedForce<Dim> linked_force(std::span<const LubricationLink<Dim>> links, const Vec<Dim>& velocity,
                              const AngularVec<Dim>& omega, std::span<const Particle<Dim>> bodies)
{
    LinkedForce<Dim> f;
    for (const LubricationLink<Dim>& link : links) {
        const Vec<Dim> relative =
            velocity + cross(omega, link.lever) - partner_surface_velocity<Dim>(link, bodies);
        const Vec<Dim> force = -(gap_resistance<Dim>(link.normal, link.resistance) * relative);
        f.force += force;
        f.moment += cross(link.lever, force);
    }
    return f;
}

template <int Dim>
std::vector<Vec<Dim>> coupled_velocities(std::span<const Particle<Dim>> bodies,
                                         std::span<const std::size_t> members,
                                         std::span<const RigidBalance<Dim>> balances)
{
    const auto size = static_cast<Eigen::Index>(Dim * members.size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd right(size);
    const auto add_block = [&](std::size_t row, std::size_t column, const Matrix<Dim>& block) {
        for (int r = 0; r < Dim; ++r) {
            for (int c = 0; c < Dim; ++c) {
                entries.emplace_back(static_cast<Eigen::Index>(Dim * row) + r,
                                     static_cast<Eigen::Index>(Dim * column) + c, block(r, c));
            }
        }
    };
    for (std::size_t m = 0; m < members.size(); ++m) {
        const Particle<Dim>& body = bodies[members[m]];
        Matrix<Dim> diagonal = balances[m].mass_rate * Matrix<Dim>::Identity();
        Vec<Dim> b = balances[m].impulse_rate;
        for (const LubricationLink<Dim>& link : body.contact.lubrication_links) {
            const Matrix<Dim> c = gap_resistance<Dim>(link.normal, link.resistance);
            diagonal += c;
            b -= c * cross(body.omega, link.lever);
            const auto partner = std::find(members.begin(), members.end(), link.partner);
            if (partner == members.end()) {
                b += c * partner_surface_velocity<Dim>(link, bodies);
                continue;
            }
            b += c * cross(bodies[link.partner].omega, link.partner_lever);
            add_block(m, static_cast<std::size_t>(partner - members.begin()), Matrix<Dim>(-c));
        }
        add_block(m, m, diagonal);
        right.segment<Dim>(static_cast<Eigen::Index>(Dim * m)) = b;
    }
    Eigen::SparseMatrix<double> system(size, size);
    system.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factors(system);
    const Eigen::VectorXd solution = factors.solve(right);
    std::vector<Vec<Dim>> velocities(members.size());
    for (std::size_t m = 0; m < members.size(); ++m) {
        velocities[m] = solution.segment<Dim>(static_cast<Eigen::Index>(Dim * m));
    }
    return velocities;
}

template <int Dim>
LinkedGroups linked_groups(std::span<const Particle<Dim>> bodies, bool is_paper_contact)
{
    // Union–find over the links between bodies eqs. (13)–(14) move; each root is the smallest
    // index of its set, so the groups come out in store order.
    const std::size_t n = bodies.size();
    std::vector<std::size_t> root(n);
    for (std::size_t b = 0; b < n; ++b) {
        root[b] = b;
    }
    const auto find = [&](std::size_t b) {
        while (root[b] != b) {
            root[b] = root[root[b]];
            b = root[b];
        }
        return b;
    };
    std::vector<char> is_member(n, 0);
    for (std::size_t b = 0; b < n; ++b) {
        const Particle<Dim>& body = bodies[b];
        if (!is_moved_by_fluid(body, is_paper_contact) || body.contact.lubrication_links.empty()) {
            continue;
        }
        is_member[b] = 1;
        for (const LubricationLink<Dim>& link : body.contact.lubrication_links) {
            if (link.partner == LubricationLink<Dim>::wall ||
                !is_moved_by_fluid(bodies[link.partner], is_paper_contact)) {
                continue;
            }
            const std::size_t x = find(b);
            const std::size_t y = find(link.partner);
            root[std::max(x, y)] = std::min(x, y);
        }
    }
    LinkedGroups out(n);
    std::vector<int> group_of_root(n, -1);
    for (std::size_t b = 0; b < n; ++b) {
        if (is_member[b] == 0) {
            continue;
        }
        const std::size_t r = find(b);
        if (group_of_root[r] < 0) {
            group_of_root[r] = static_cast<int>(out.groups.size());
            out.groups.emplace_back();
        }
        out.group_of[b] = group_of_root[r];
        out.groups[static_cast<std::size_t>(group_of_root[r])].push_back(b);
    }
    return out;
}

template <int Dim>
void drop_substep_lubrication(std::span<Particle<Dim>> bodies, bool is_paper_contact)
{
    for (Particle<Dim>& body : bodies) {
        if (!is_moved_by_fluid(body, is_paper_contact)) {
            continue;
        }
        ContactState<Dim>& c = body.contact;
        c.mean_force -= c.lubrication_force;
        c.mean_torque -= c.lubrication_torque;
        c.lubrication_force = Vec<Dim>::Zero();
        c.lubrication_torque = zero_angular<Dim>();
    }
}

template <int Dim>
void record_linked_lubrication(std::span<Particle<Dim>> bodies, bool is_paper_contact)
{
    for (Particle<Dim>& body : bodies) {
        if (!is_moved_by_fluid(body, is_paper_contact) || body.contact.lubrication_links.empty()) {
            continue;
        }
        ContactState<Dim>& c = body.contact;
        const LinkedForce<Dim> f =
            linked_force<Dim>(c.lubrication_links, body.velocity, body.omega, bodies);
        c.lubrication_force = f.force;
        c.lubrication_torque = f.moment;
        c.mean_force += f.force;
        c.mean_torque += f.moment;
    }
}

#define FDDEM_INSTANTIATE_LUBRICATION_COUPLING(DIM)                                                \
    template Matrix<DIM> gap_resistance<DIM>(const Vec<DIM>&, const LubricationResistance&);       \
    template Vec<DIM> partner_surface_velocity<DIM>(const LubricationLink<DIM>&,                   \
                                                    std::span<const Particle<DIM>>);               \
    template LinkedDamping<DIM> linked_damping<DIM>(std::span<const LubricationLink<DIM>>,         \
                                                    const Vec<DIM>&, const AngularVec<DIM>&,       \
                                                    std::span<const Particle<DIM>>);               \
    template LinkedForce<DIM> linked_force<DIM>(std::span<const LubricationLink<DIM>>,             \
                                                const Vec<DIM>&, const AngularVec<DIM>&,           \
                                                std::span<const Particle<DIM>>);                   \
    template std::vector<Vec<DIM>> coupled_velocities<DIM>(std::span<const Particle<DIM>>,         \
                                                           std::span<const std::size_t>,           \
                                                           std::span<const RigidBalance<DIM>>);    \
    template LinkedGroups linked_groups<DIM>(std::span<const Particle<DIM>>, bool);                \
    template void drop_substep_lubrication<DIM>(std::span<Particle<DIM>>, bool);                   \
    template void record_linked_lubrication<DIM>(std::span<Particle<DIM>>, bool);
FDDEM_INSTANTIATE_LUBRICATION_COUPLING(2)
FDDEM_INSTANTIATE_LUBRICATION_COUPLING(3)
#undef FDDEM_INSTANTIATE_LUBRICATION_COUPLING

} // namespace fddem
