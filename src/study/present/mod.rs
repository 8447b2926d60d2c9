//! What the study shows: [`report`] writes tables for people and CSV for
//! programs; [`swatches`] renders every light × patch by every method as
//! swatches whose pixels are independent estimates, and [`sheet`] lays
//! them out as one labelled image (8-bit sRGB rows, with a built-in bitmap
//! font: no system fonts, no image library).
//!
//! ```
//! use speclab::study::evaluate::scene;
//! use speclab::study::present::{sheet, swatches::{self, SwatchOptions}};
//! let (lights, patches) = (&scene::builtin_lights()[..1], &scene::builtin_surfaces()[..1]);
//! let options = SwatchOptions { size: 4, ..SwatchOptions::default() };
//! let shown = swatches::render(lights, patches, &options)?;
//! let layout = sheet::Layout::new(&shown);
//! assert_eq!(sheet::draw(&shown).len(), 3 * layout.width() * layout.height());
//! # Ok::<(), speclab::study::StudyError>(())
//! ```

mod font;
pub mod report;
pub mod sheet;
pub mod swatches;
