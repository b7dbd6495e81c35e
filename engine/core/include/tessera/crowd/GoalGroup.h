#pragma once
/// @file GoalGroup.h
/// A destination shared by a group of agents: one potential field each.

#include "tessera/crowd/Region.h"

#include <string>

namespace tessera::crowd {

/// What an agent does once it stands inside its goal region.
enum class ArrivalPolicy {
    /// Takes another group's goal (chosen from its own seeded sequence) and
    /// walks on: endless wandering between the goals.
    Wander,
    /// Walks to a spot of its own inside the region (so arrivals spread out
    /// instead of blocking the entrance) and idles there.
    Stay,
};

/// One goal group: every agent of the group walks down the same potential
/// field, solved once per group (continuum crowds' unit of work).
struct GoalGroup {
    std::string name;
    Region region;
    ArrivalPolicy onArrival = ArrivalPolicy::Wander;
};

} // namespace tessera::crowd
