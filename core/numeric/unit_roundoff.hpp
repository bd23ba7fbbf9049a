#pragma once

namespace bezier::core {

/// The unit roundoff u of double arithmetic (round to nearest, 53-bit significand): every
/// operation's result is the exact one times (1 + d) with |d| <= u, away from underflow and
/// overflow (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., §2.2). The
/// error bounds of the kernel are written in multiples of it.
inline constexpr double kUnitRoundoff = 0x1p-53;

}  // namespace bezier::core
