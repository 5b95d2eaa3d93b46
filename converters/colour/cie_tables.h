// Tabulated CIE colorimetric data (see cie_tables.cpp for the source of the numbers).
#pragma once

namespace rayset {

// CIE 1924 photopic V(lambda), 1 nm steps from kCiePhotopicFirst to kCiePhotopicLast nm.
inline constexpr int kCiePhotopicFirst = 360;
inline constexpr int kCiePhotopicLast = 830;
inline constexpr int kCiePhotopicCount = kCiePhotopicLast - kCiePhotopicFirst + 1;
extern const double kCiePhotopic[kCiePhotopicCount];

}  // namespace rayset
