//! Planetary (2K-H) gear trains: tooth-number synthesis, conditions, velocity pictures (no I/O).
