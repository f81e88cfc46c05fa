// SPDX-License-Identifier: MIT
#include "fddem/coupling/markers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace fddem {
namespace {

template <class T>
class Markers : public ::testing::Test {
};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Markers, Dimensions);

TYPED_TEST(Markers, VolumesSumToTheBodyAndTheCentroidIsTheCentre)
{
    constexpr int Dim = TypeParam::value;
    const Ball<Dim> ball{0.25};
    for (const int n_rings : {1, 3, 6, 14}) {
        const MarkerSet<Dim> set = make_ball_markers(ball, n_rings);
        double volume = 0.0;
        Vec<Dim> first = Vec<Dim>::Zero();
        for (std::size_t l = 0; l < set.size(); ++l) {
            volume += set.volumes[l];
            first += set.volumes[l] * set.offsets[l];
            EXPECT_TRUE(ball.contains(set.offsets[l]));
        }
        EXPECT_NEAR(volume / ball.volume(), 1.0, 1e-13) << n_rings;
        EXPECT_LT(first.norm(), 1e-15 * ball.radius() * ball.volume());
        // Each ring stands for its annulus (shell) at the mid radius: the midpoint rule puts
        // the second moment short by about 1/(2 (N_a + ½)²) of it in 2D, 0.7/(N_a + ½)² in 3D.
        // The fluid inertia in eq. (14) uses the markers' own moment, so this is no error there.
        const double relative = set.second_moment() / ball.second_moment();
        EXPECT_LT(relative, 1.0);
        EXPECT_GT(relative, 1.0 - 0.8 / ((n_rings + 0.5) * (n_rings + 0.5))) << n_rings;
    }
}

TYPED_TEST(Markers, RetractedLayoutKeepsTheVolumeAndPutsTheLastRingInsideBy)
{
    constexpr int Dim = TypeParam::value;
    const Ball<Dim> ball{1.0}; // D = 1
    const double h = 1.0 / 32; // R = 16 h
    for (const double retraction : {0.0, 0.3 * h, 0.7 * h}) {
        const int n_rings = retracted_rings_for_spacing(ball.radius(), retraction, h, 2.0);
        const MarkerSet<Dim> set = make_retracted_ball_markers(ball, n_rings, retraction);
        double volume = 0.0;
        double outermost = 0.0;
        for (std::size_t l = 0; l < set.size(); ++l) {
            volume += set.volumes[l];
            outermost = std::max(outermost, set.offsets[l].norm());
        }
        EXPECT_NEAR(volume / ball.volume(), 1.0, 1e-13);
        EXPECT_NEAR(outermost, ball.radius() - retraction, 1e-14);
        EXPECT_EQ(set.outermost_radius(), outermost); // the lubrication's shell depth R − it
        // (R − r)/(2 h) = 8, 7.85, 7.65 → 8 rings of spacing ≈ 2 h.
        EXPECT_EQ(n_rings, 8);
        EXPECT_NEAR(set.spacing, (ball.radius() - retraction) / 8, 1e-15);
        // The second moment: the last ring stands for the band out to R at the band's inner
        // part (or its outer edge, without retraction): within a ring spacing's share of R².
        EXPECT_NEAR(set.second_moment() / ball.second_moment(), 1.0,
                    2.0 * set.spacing / ball.radius());
    }
}

TEST(Markers, RetractedLayoutWithoutRetractionIsNotThePapers)
{
    // The paper's layout keeps its last ring h_L/2 inside; retraction 0 puts it on the surface.
    const auto paper = make_ball_markers(Ball<2>{2.0}, 6); // R = 1
    const auto surface = make_retracted_ball_markers(Ball<2>{2.0}, 6, 0.0);
    EXPECT_NEAR(paper.offsets.back().norm(), 6.0 / 6.5, 1e-15);
    EXPECT_NEAR(surface.offsets.back().norm(), 1.0, 1e-15);
    EXPECT_NEAR(paper.outermost_radius(), 6.0 / 6.5, 1e-15);
    EXPECT_EQ(MarkerSet<2>{}.outermost_radius(), 0.0);
    EXPECT_EQ(paper.size(), surface.size());
}

TYPED_TEST(Markers, SurfaceLayoutIsOneRingOfShellsOfThicknessH)
{
    // coupling.markers = "surface": the retracted layout's outermost ring alone, markers about
    // the target spacing apart, their volumes summing to the shell of thickness h on it.
    constexpr int Dim = TypeParam::value;
    const Ball<Dim> ball{1.0};
    const double h = 1.0 / 20;
    const double retraction = 0.3 * h;
    const double r = ball.radius() - retraction;
    const MarkerSet<Dim> set = make_surface_ball_markers(ball, retraction, 1.4 * h, h);
    double volume = 0.0;
    double nearest = 10.0; // the closest pair, the spacing of the ring
    for (std::size_t l = 0; l < set.size(); ++l) {
        volume += set.volumes[l];
        EXPECT_NEAR(set.offsets[l].norm(), r, 1e-14);
        for (std::size_t m = l + 1; m < set.size(); ++m) {
            nearest = std::min(nearest, (set.offsets[l] - set.offsets[m]).norm());
        }
    }
    const double area = Dim == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r;
    EXPECT_NEAR(volume / (area * h), 1.0, 1e-13);
    // 2D: 6i markers π r/(3i) apart on the ring, i = round(π r/(3 · 1.4 h)) = 7: 42 markers.
    // 3D: 8 round(π i²/2) markers with i = round(r/(1.4 h)) = 7: 616, against the sphere's area
    // over the spacing squared, 603 (the mirrored spiral puts some pairs closer: the count, not
    // the nearest pair, is the spacing's measure there).
    if constexpr (Dim == 2) {
        EXPECT_EQ(set.size(), 42U);
        EXPECT_NEAR(nearest / (1.4 * h), 1.0, 0.1);
    } else {
        EXPECT_EQ(set.size(), 616U);
        EXPECT_NEAR(static_cast<double>(set.size()) * std::pow(1.4 * h, 2) / area, 1.0, 0.05);
    }
}

/// Every marker layout of a `Dim`-D ball, by name, as a function of N_a. A new layout (the
/// sphere shells of the "3D spheres" issue, say) is one more entry here, and the symmetry test
/// below holds it to the same standard.
template <int Dim>
std::vector<std::pair<std::string, std::function<MarkerSet<Dim>(const Ball<Dim>&, int)>>>
marker_layouts()
{
    return {{"make_ball_markers",
             [](const Ball<Dim>& ball, int n_rings) { return make_ball_markers(ball, n_rings); }},
            {"make_retracted_ball_markers",
             [](const Ball<Dim>& ball, int n_rings) {
                 return make_retracted_ball_markers(ball, n_rings, 0.1 * ball.radius());
             }},
            {"make_surface_ball_markers", [](const Ball<Dim>& ball, int n_rings) {
                 // spacing R/N_a: one ring of about as many markers as the N_a-th ring has
                 return make_surface_ball_markers(ball, 0.1 * ball.radius(),
                                                  ball.radius() / n_rings, ball.radius() / 20);
             }}};
}

TYPED_TEST(Markers, EveryLayoutIsMirrorSymmetricWithItsCentroidAtTheCentreToRoundOff)
{
    // Issue 17: a sphere settling in a symmetric box drifted sideways at 1.5 % of its fall
    // speed: its golden-spiral shells put the marker centroid up to 1 % of R off the centre.
    // Each marker needs a twin with its volume in the mirror image through each plane of the
    // axes (the symmetries of a body settling in a symmetric box); the centroid is then the
    // centre to round-off, and a drift of 1e-12 R fails.
    constexpr int Dim = TypeParam::value;
    const Ball<Dim> ball{0.25};
    const double r = ball.radius();
    for (const auto& [name, layout] : marker_layouts<Dim>()) {
        // Up to N_a = 8 in 3D (2 600 markers): the pairwise twin search is quadratic, and the
        // sanitizer build runs it too.
        for (int n_rings = 1; n_rings <= (Dim == 2 ? 16 : 8); ++n_rings) {
            const MarkerSet<Dim> set = layout(ball, n_rings);
            Vec<Dim> first = Vec<Dim>::Zero();
            double volume = 0.0;
            for (std::size_t l = 0; l < set.size(); ++l) {
                first += set.volumes[l] * set.offsets[l];
                volume += set.volumes[l];
                for (int axis = 0; axis < Dim; ++axis) {
                    Vec<Dim> image = set.offsets[l];
                    image[axis] = -image[axis];
                    const auto twin = std::find_if(
                        set.offsets.begin(), set.offsets.end(),
                        [&](const Vec<Dim>& o) { return (o - image).norm() < 1e-12 * r; });
                    ASSERT_NE(twin, set.offsets.end())
                        << name << ", N_a = " << n_rings << ": marker " << l << " has no mirror "
                        << "image through plane " << axis;
                    EXPECT_EQ(set.volumes[static_cast<std::size_t>(twin - set.offsets.begin())],
                              set.volumes[l])
                        << name << ", N_a = " << n_rings << ", marker " << l;
                }
            }
            EXPECT_LT((first / volume).norm(), 1e-12 * r) << name << ", N_a = " << n_rings;
        }
    }
}

TEST(Markers, DiskHasTheLayoutOfPaperFigure1)
{
    for (const int n_rings : {6, 12, 13, 14}) {
        const auto set = make_ball_markers(Ball<2>{1.0}, n_rings);
        EXPECT_EQ(set.size(), static_cast<std::size_t>(1 + 3 * n_rings * (n_rings + 1)));
    }
}

TEST(Markers, RingsFromSpacingRatio)
{
    // h = D/16 (R = 8h) at h_L ≈ 1.4 h: R/(1.4 h) − ½ = 5.2 → 5 rings.
    EXPECT_EQ(rings_for_spacing(0.5, 1.0 / 16, 1.4), 5);
    EXPECT_EQ(rings_for_spacing(0.01, 1.0, 1.4), 1);
}

} // namespace
} // namespace fddem
