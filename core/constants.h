#pragma once
// Tuning constants shared by the core and both front ends. Units in the comments.

namespace bsim {

/// s from the start event to the cue strike: room for the stick's approach and two practice strokes.
inline constexpr double kCueLeadTime = 2.5;

/// Horizontal field of view of the scene camera in degrees, the same for POV-Ray and the GL preview.
inline constexpr double kCameraFovDeg = 55.0;

/// Cue stick dimensions, m.
inline constexpr double kCueLength = 1.47;
inline constexpr double kCueTipRadius = 0.0065;
inline constexpr double kCueButtRadius = 0.0145;

/// Sound track sample rate, Hz.
inline constexpr int kSampleRate = 48000;

}  // namespace bsim
