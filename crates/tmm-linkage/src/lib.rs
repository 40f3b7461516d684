//! Planar lever mechanisms: description, structural analysis, kinematics, kinetostatics (no I/O).
