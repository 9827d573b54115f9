//! Re-running a job with a change, for the diagnosis's remedies (`analysis::diagnose`): the
//! main program's text changed ([`Change::edited`]), or the tool table with one tool
//! replaced, read and expanded as the first time and run on the same blank, machine and
//! tolerance.

use crate::job::Job;
use analysis::diagnose::{Change, Rerun, Rerunning};

/// A job, its tolerance and its run's memory budget, re-runnable.
pub(crate) struct Rerunner<'a> {
    pub(crate) job: &'a Job,
    pub(crate) tol: f64,
    pub(crate) memory: Option<stock::RunMemory>,
}

impl Rerun for Rerunner<'_> {
    fn rerun(&self, change: &Change) -> Option<Rerunning> {
        let loaded = &self.job.loaded;
        let (text, tools) = match change {
            Change::Tool { t, entry } => (
                loaded.source.text.to_string(),
                self.job.tools.replaced(*t, entry).ok()?,
            ),
            program => (program.edited(&loaded.source.text)?, self.job.tools.clone()),
        };
        let program = gcode::parse_with(&text, loaded.read).ok()?;
        let opts = expander::Options {
            tools: tools.facts(),
            ..loaded.opts.clone()
        };
        let toolpath = expander::expand(&program, &loaded.machine, &opts);
        let settings = analysis::Settings {
            tools: &tools,
            ..self.job.settings(self.tol)
        };
        let opts = stock::SimOptions {
            max_memory: self.memory.clone(),
            ..stock::SimOptions::default()
        };
        let (sim, findings) =
            analysis::pipeline(&toolpath, &self.job.intents, &settings, &opts, &mut |_| {});
        // a re-run stopped over the budget checks nothing
        if sim.over_budget.is_some() {
            return None;
        }
        Some(Rerunning {
            findings,
            part: sim.final_shapes,
            alarms: toolpath.alarms.len(),
        })
    }
}
