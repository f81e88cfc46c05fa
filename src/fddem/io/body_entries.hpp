// SPDX-License-Identifier: MIT
#pragma once
/// The bodies of a case from its [[bodies]] entries (issue 14). An entry gives
///
/// - one body, at its `position`; or
/// - one body per row of its `file` (io/body_file.hpp), a CSV relative to the case file; or
/// - `count` bodies (or as many as fill `volume_fraction` of the region) inserted at random
///   (io/random_packing.hpp) in the box `region_low`–`region_high` (default: the whole box),
///   clear of the bodies of every other entry.
///
/// The entry is the template of each body it gives: shape, motion, n_rings, the surface keys
/// and (unless the file has u, v, w) velocity are the entry's; a file gives position, diameter
/// and density, and takes none of them from the entry. One entry per kind of body keeps the
/// schema's one row per key (no second table of body keys), and lets a case mix a bed from a
/// file with bodies given one by one.
///
/// Ids: a file gives its bodies' ids (unique in the case); every other entry numbers its bodies
/// on from the largest id of the entries before it (from 0), so a case without files has the
/// ids 0, 1, 2… in the order of its entries, as before files existed.
///
/// The case as run records a file by its absolute path (a restart reads the case in the run
/// directory) and the seed of a random insertion, so that it reads back to the same bodies.

#include "fddem/simulation/case_config.hpp"

namespace fddem {

class CaseDocument;

/// The most bodies one random insertion places (bodies.count, or from bodies.volume_fraction):
/// a bound on the reader's time and memory (about 1.4 kB and 7 µs per body as read; a bed of more
/// resolved bodies than this needs ~10^10 cells, and comes from a file).
/// The fuzz build (fuzz/CMakeLists.txt) sets a small bound, so that libFuzzer's per-input
/// timeout catches hangs and not large valid insertions (170 µs per body under ASan).
#ifdef FDDEM_MAX_INSERTED_BODIES
inline constexpr long max_inserted_bodies = FDDEM_MAX_INSERTED_BODIES;
#else
inline constexpr long max_inserted_bodies = 1'000'000;
#endif

/// Replaces `c.bodies` (one template per [[bodies]] entry, as the keys were read) with the
/// bodies the entries give. Each problem stops with the file, the line and the key (for a body
/// file: its line and column).
void make_bodies(CaseDocument& doc, CaseConfig& c);

/// Each entry's `file` by its absolute path in the case as run; last, as the new value has no
/// line in the case for messages.
void record_body_files(CaseDocument& doc, const CaseConfig& c);

} // namespace fddem
