//! Per-suit tables (filled in by the tables work).
