//! Cam mechanisms: motion laws, sizing, profiles (no I/O).
