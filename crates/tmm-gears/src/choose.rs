//! Choosing x1, x2 by a named criterion.
