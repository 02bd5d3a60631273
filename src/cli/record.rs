//! `simulate --bag DIR`: the CLI's end of `bag::offline` (which needs the
//! node's message code, so the `ros` feature; without it `--bag` says so).

use super::error::{CliError, CliResult};
use crate::dynamics::Simulation;
use std::path::Path;

/// A bag being recorded from an offline run.
pub struct BagOutput {
    #[cfg(feature = "ros")]
    inner: crate::bag::OfflineRecorder,
}

#[cfg(feature = "ros")]
impl BagOutput {
    /// Create the rosbag2 directory `dir` (it must not exist) for the scene
    /// `file` with its `-p` overrides (its `ros.*` keys: frame prefix, world
    /// frame, diagnostics period, marker).
    pub fn create(
        dir: &Path,
        sim: &Simulation,
        file: &Path,
        overrides: &[String],
    ) -> CliResult<BagOutput> {
        use crate::messages::settings::RosSettings;
        let usage = |e: String| CliError::Usage(format!("{}: {e}", file.display()));
        let params = super::params_with_overrides(file, overrides)?;
        let settings = RosSettings::from_params(&params).map_err(|e| usage(e.to_string()))?;
        settings
            .check_against_rate(1.0 / sim.dt())
            .map_err(|e| usage(e.to_string()))?;
        let inner = crate::bag::OfflineRecorder::create(dir, sim, &settings)
            .map_err(|e| CliError::Usage(format!("--bag: {e}")))?;
        Ok(BagOutput { inner })
    }

    /// Record the current state (t = 0, then after every step).
    pub fn record(&mut self, sim: &Simulation) -> CliResult<()> {
        self.inner
            .record(sim)
            .map_err(|e| CliError::Usage(format!("--bag: {e}")))
    }

    /// Finish the bag; returns a one-line summary.
    pub fn finish(self) -> CliResult<String> {
        let s = self
            .inner
            .finish()
            .map_err(|e| CliError::Usage(format!("--bag: {e}")))?;
        let topics: Vec<String> = s
            .topics
            .iter()
            .map(|t| format!("{} {}", t.name, t.count))
            .collect();
        Ok(format!(
            "bag {}: {} messages ({}), {:.3} s, {} bytes",
            s.dir.display(),
            s.message_count,
            topics.join(", "),
            s.duration as f64 * 1e-9,
            s.bytes
        ))
    }
}

#[cfg(not(feature = "ros"))]
impl BagOutput {
    pub fn create(
        _dir: &Path,
        _sim: &Simulation,
        _file: &Path,
        _overrides: &[String],
    ) -> CliResult<BagOutput> {
        return Err(CliError::Usage(format!(
            "--bag needs the `ros` feature (the bag holds the node's messages); this build has none: build with the default features"
        )));
    }
    pub fn record(&mut self, _sim: &Simulation) -> CliResult<()> {
        Ok(())
    }
    pub fn finish(self) -> CliResult<String> {
        Ok(String::new())
    }
}
