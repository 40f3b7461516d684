//! Blocking contour (блокирующий контур) in the x1–x2 plane.
