//! The intended part and the deviation of the final part from it.

use crate::cli::RunArgs;
use crate::input::{self, Loaded};
use expander::IntendedKind;
use stock::Intent;

/// The intents: `--target F`, else the shapes the program defines for itself.
pub(crate) fn intents(args: &RunArgs, loaded: &Loaded) -> Result<Vec<Intent>, ()> {
    if let Some(path) = &args.target {
        let text = input::read_text(path, "target")?;
        let part = stock::profile_from_toml(&text, 0.001)
            .map_err(|e| input::print_stock_error(path, &text, &e))?;
        return Ok(vec![Intent::target(part)]);
    }
    Ok(loaded
        .toolpath
        .intended
        .iter()
        .filter_map(|i| {
            let pts: Vec<[f64; 2]> = i.points.iter().map(|p| [p.z, p.r]).collect();
            match i.kind {
                IntendedKind::Groove => Some(Intent::groove(&pts)),
                IntendedKind::FinishingContour => Intent::finishing(&pts),
                IntendedKind::Compensated { part_on_left } => {
                    Intent::compensated(&pts, part_on_left)
                }
            }
        })
        .collect())
}
