//! Regression snapshots: numbers this project computed itself and keeps so
//! that a change cannot move them unnoticed (not published truth).

mod fitted;
