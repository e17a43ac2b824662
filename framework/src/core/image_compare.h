#pragma once
// How two renders of the same view are compared, everywhere in RayLab (tests,
// `raylab check`, grading). See tests/README.md for why these numbers.
#include "image.h"

#include <string>

namespace raylab {

struct ImageDiff {
    int badPixels = 0;      // pixels with no close match in the other image's 3x3 neighbourhood
    double badShare = 0.0;  // badPixels / all pixels
    int maxDiff = 0;  // largest per-channel difference (0..255) after the neighbourhood search
    bool sameSize = true;
};

struct CompareTolerance {
    int channel =
        8;  // a pixel matches if some neighbour differs by at most this in every channel (of 255)
    double maxBadShare = 0.005;  // the images agree if at most this share of pixels has no match
};

// For each pixel of A, the smallest difference (max over RGB) to a pixel of B
// in the 3x3 neighbourhood around the same position, and the same from B to A:
// a one-pixel shift of an edge (rasterisation, float rounding on another GPU)
// is not counted as a difference, a wrong colour or a moved object is.
ImageDiff compareImages(const Image& a, const Image& b, int channelTolerance);

bool imagesAgree(const ImageDiff& diff, const CompareTolerance& tol);

// "0.12% of pixels differ (max 37/255)"
std::string describe(const ImageDiff& diff);

// What a hint may say beyond the picture's facts.
struct DiagnoseContext {
    // The stage's usual causes of a picture that is mostly too dark or too
    // bright (stage.json "hints"); empty: the fact alone. A stage of flat
    // colours has no lighting causes to suggest.
    std::string darkerCause, brighterCause;
    // Pixels of MINE whose computation reached a TODO stub, as the shader
    // itself marked them (never guessed from magenta: a violet sphere is
    // magenta too). Which stub is not known: the hint does not name one.
    long todoPixels = 0;
    long nonFinite = 0;  // NaN/Inf pixels of MINE (drawn magenta): the hint is about them
};

// A hint at what is wrong, for students ("" when nothing stands out): NaN
// pixels, pixels that reached a TODO stub, a picture of one flat colour
// (with the colour: not guessed to be the background), mostly too dark,
// mostly too bright.
std::string diagnose(const Image& mine, const Image& expected, int channelTolerance,
                     const DiagnoseContext& context = {});

// A heat map of the per-pixel difference (black = equal, red = max), for reports.
Image diffHeatMap(const Image& a, const Image& b);

}  // namespace raylab
