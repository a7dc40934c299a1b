#pragma once
// `lenslab lens --plot FILE.svg`: the lens drawn in section with rays traced through it from three
// points of the field, beside its distortion and relative illumination against field.
#include "lens/LensAnalysis.h"
#include "lens/LensPrescription.h"

#include <string>

namespace lenslab {

std::string lensPlotSvg(const LensPrescription& lens, const LensReport& report, const LensAnalysisOptions& options);

}  // namespace lenslab
