// The short written reading of each chart: what is worth its cost, written from the measured
// numbers of that run (never canned), so it changes when the numbers change.
#pragma once

#include "report/model.h"

#include <string>
#include <vector>

namespace twr::report {

struct KnobReading {
  std::string summary;  // one or two sentences for the list at the top of the report
  std::string detail;   // the numbers behind it, per backend, under the knob's heading
};

KnobReading readKnob(const KnobResult& knob);
KnobReading readBases(const std::vector<BasisRow>& rows);
// The environment section: which mapping loses less at which size, how fast each error falls
// with the size, and where each one's worst direction sits.
KnobReading readParameterizations(const ParameterizationSection& section);
KnobReading readDiffuseLight(const DiffuseLightSection& section);
KnobReading readShadows(const ShadowSection& section);
KnobReading readGlossy(const GlossySection& section);
// Screen-space reflections against the ray tracer: how many steps each march needs to reach
// linear_world's best error and what those frames cost, where the thickness threshold leaks
// (false hits) or loses (missed surfaces), and how the indirect light's noise falls with samples.
KnobReading readSsr(const SsrSection& section);
// The height-field section across its views: which method is worth its cost at which angle,
// POM against plain parallax, where steep parallax's stair-steps show, how many layers POM
// needs to beat relief, and the 720p cost line.
KnobReading readHeightFields(const HeightFieldSection& section);

}  // namespace twr::report
