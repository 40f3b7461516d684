//! Tooth profiles by simulating generation with the rack cutter.
