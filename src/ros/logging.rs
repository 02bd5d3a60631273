//! Log lines to `/rosout` (rcl_interfaces/msg/Log) and to stderr, with the
//! level from `--log-level` and the rate limit for rejected inputs.

use super::inputs::{RateLimiter, Rejection};
use ros2_client::log::LogLevel;
use ros2_client::rosout::{NodeLoggingHandle, RosoutRaw};
use std::time::{Duration, Instant};

/// A cheap, thread-safe logger for one node.
pub struct Logger {
    handle: Option<NodeLoggingHandle>,
    name: String,
    stderr: bool,
    min_level: u8,
    limiter: RateLimiter,
}

fn level_code(level: LogLevel) -> u8 {
    level as u8
}

/// `--log-level` text → rcl level code (unknown text: info).
pub fn parse_level(text: Option<&str>) -> u8 {
    match text.map(str::to_ascii_lowercase).as_deref() {
        Some("debug") => 10,
        Some("warn") | Some("warning") => 30,
        Some("error") => 40,
        Some("fatal") => 50,
        _ => 20,
    }
}

impl Logger {
    /// `name`: the logger name (the node's name, as rclcpp uses).
    pub fn new(
        handle: Option<NodeLoggingHandle>,
        name: &str,
        stderr: bool,
        min_level: u8,
        reject_period: Duration,
    ) -> Self {
        Logger {
            handle,
            name: name.to_string(),
            stderr,
            min_level,
            limiter: RateLimiter::new(reject_period),
        }
    }

    pub fn log(&self, level: LogLevel, msg: &str) {
        if level_code(level) < self.min_level {
            return;
        }
        if self.stderr {
            let tag = match level {
                LogLevel::Debug => "DEBUG",
                LogLevel::Info => "INFO",
                LogLevel::Warn => "WARN",
                LogLevel::Error => "ERROR",
                LogLevel::Fatal => "FATAL",
            };
            eprintln!("[{tag}] [{}]: {msg}", self.name);
        }
        if let Some(h) = &self.handle {
            h.rosout_raw(
                ros2_client::builtin_interfaces::Time::now(),
                level,
                &self.name,
                msg,
                file!(),
                "",
                line!(),
            );
        }
    }

    pub fn info(&self, msg: &str) {
        self.log(LogLevel::Info, msg);
    }

    pub fn warn(&self, msg: &str) {
        self.log(LogLevel::Warn, msg);
    }

    pub fn error(&self, msg: &str) {
        self.log(LogLevel::Error, msg);
    }

    /// A rejected input on `topic`: at most one line per kind per period.
    pub fn rejection(&self, topic: &str, r: &Rejection) {
        if let Some(suppressed) = self.limiter.permit(r.reason, Instant::now()) {
            let more = if suppressed > 0 {
                format!(" ({suppressed} more of this kind since the last report)")
            } else {
                String::new()
            };
            self.warn(&format!(
                "rejected input on {topic} [{}]: {}{more}",
                r.reason.name(),
                r.detail
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels() {
        assert_eq!(parse_level(None), 20);
        assert_eq!(parse_level(Some("WARN")), 30);
        assert_eq!(parse_level(Some("debug")), 10);
        assert_eq!(parse_level(Some("bogus")), 20);
    }
}
