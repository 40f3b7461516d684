//! Involute spur gear pairs with profile shift: geometry, quality, blocking contours, generation (no I/O).
