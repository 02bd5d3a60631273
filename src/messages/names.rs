//! ROS 2 command-line arguments (`--ros-args ... [--]`), as `ros2 run` and
//! launch files pass them, and ROS 2 name resolution with remapping.
//!
//! ros2-client has no argument handling at all, so this module implements
//! the subset of rcl's rules a node needs:
//!
//! - `-r` / `--remap [node:]from:=to`, with the special names `__node`
//!   (alias `__name`) and `__ns`;
//! - `-p` / `--param [node:]name:=value` (value read as YAML by the config);
//! - `--params-file FILE` (several allowed; later ones win);
//! - `--log-level [logger:=]LEVEL`, `--enable-/--disable-rosout-logs`,
//!   `--enable-/--disable-stdout-logs` (the others of rcl's logging flags and
//!   `-e`/`--enclave` are accepted and ignored).
//!
//! A ROS argument list may hold several `--ros-args` blocks, each ended by
//! `--` or by the end of the list. A list without any `--ros-args` is read
//! as one block (the caller already stripped the marker). Anything unknown
//! inside a block is an error, as in rcl, so a typo never goes unnoticed.
//!
//! Pure functions only: no ROS types, no I/O; unit-tested below.

use std::fmt;

/// The node's name when none is given (`-r __node:=…`), and the entry the CLI reads from a params file.
pub const DEFAULT_NODE_NAME: &str = "annular_plate";
use std::path::PathBuf;

/// A remapping rule `[node:]from:=to` for topic and service names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Remap {
    /// Applies only to this node (by name) when given.
    pub node: Option<String>,
    pub from: String,
    pub to: String,
}

/// A parameter given on the command line: `-p [node:]name:=value`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParamArg {
    pub node: Option<String>,
    pub name: String,
    /// The value as text (YAML: `0.5`, `true`, `[1, 2]`, `clamped`).
    pub value: String,
}

/// Parsed ROS arguments.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct RosArgs {
    /// `-r __node:=NAME` (or `__name`); per-node rules are kept in `node_renames`.
    node_renames: Vec<(Option<String>, String)>,
    /// `-r __ns:=/NS`.
    namespace_rules: Vec<(Option<String>, String)>,
    pub remaps: Vec<Remap>,
    pub params_files: Vec<PathBuf>,
    pub params: Vec<ParamArg>,
    /// `--log-level LEVEL` for this node's logger (or the default logger).
    pub log_level: Option<String>,
    /// `--disable-rosout-logs` clears it.
    pub rosout_logs: bool,
    /// `--disable-stdout-logs` clears it.
    pub stdout_logs: bool,
}

/// Why the ROS arguments were refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ArgsError {
    /// A flag that takes a value was last.
    MissingValue { flag: String },
    /// Not a ROS argument (inside `--ros-args`), or outside of any block.
    Unknown { arg: String },
    /// A remap or parameter rule without `:=`.
    BadRule {
        flag: String,
        rule: String,
        reason: String,
    },
    /// An invalid node name, namespace or topic name.
    BadName { name: String, reason: String },
    /// `ROS_DOMAIN_ID` is not an integer in 0..=232.
    BadDomainId { value: String },
}

impl fmt::Display for ArgsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ArgsError::MissingValue { flag } => write!(f, "the ROS argument {flag} needs a value"),
            ArgsError::Unknown { arg } => write!(
                f,
                "unknown ROS argument `{arg}` (known: -r/--remap, -p/--param, --params-file, --log-level, -e/--enclave, --enable-/--disable-rosout-logs, --enable-/--disable-stdout-logs)"
            ),
            ArgsError::BadRule { flag, rule, reason } => write!(f, "bad {flag} rule `{rule}`: {reason}"),
            ArgsError::BadName { name, reason } => write!(f, "`{name}` is not a valid ROS name: {reason}"),
            ArgsError::BadDomainId { value } => {
                write!(f, "ROS_DOMAIN_ID=`{value}` is not a domain id (an integer from 0 to 232)")
            }
        }
    }
}

impl std::error::Error for ArgsError {}

const IGNORED_WITH_VALUE: &[&str] = &["-e", "--enclave", "--log-config-file", "--log-file-name"];
const IGNORED_FLAGS: &[&str] = &["--enable-external-lib-logs", "--disable-external-lib-logs"];

impl RosArgs {
    /// Parse ROS arguments (see the module documentation).
    pub fn parse<S: AsRef<str>>(args: &[S]) -> Result<RosArgs, ArgsError> {
        let args: Vec<&str> = args.iter().map(AsRef::as_ref).collect();
        let mut out = RosArgs {
            rosout_logs: true,
            stdout_logs: true,
            ..RosArgs::default()
        };
        let has_marker = args.contains(&"--ros-args");
        let mut in_block = !has_marker;
        let mut i = 0;
        while i < args.len() {
            let arg = args[i];
            i += 1;
            if arg == "--ros-args" {
                in_block = true;
                continue;
            }
            if !in_block {
                return Err(ArgsError::Unknown {
                    arg: arg.to_string(),
                });
            }
            if arg == "--" {
                in_block = !has_marker;
                continue;
            }
            let mut value = |flag: &str| -> Result<&str, ArgsError> {
                let v = args
                    .get(i)
                    .copied()
                    .ok_or_else(|| ArgsError::MissingValue {
                        flag: flag.to_string(),
                    })?;
                i += 1;
                Ok(v)
            };
            match arg {
                "-r" | "--remap" => {
                    let rule = value(arg)?;
                    out.add_remap(arg, rule)?;
                }
                "-p" | "--param" => {
                    let rule = value(arg)?;
                    let (node, name, v) = split_rule(arg, rule)?;
                    if name.is_empty() {
                        return Err(bad_rule(arg, rule, "the parameter name is empty"));
                    }
                    out.params.push(ParamArg {
                        node,
                        name: name.to_string(),
                        value: v.to_string(),
                    });
                }
                "--params-file" => out.params_files.push(PathBuf::from(value(arg)?)),
                "--log-level" => {
                    let v = value(arg)?;
                    // `logger:=level` sets one logger; a bare level sets the default.
                    let level = v.rsplit_once(":=").map_or(v, |(_, level)| level);
                    out.log_level = Some(level.to_ascii_lowercase());
                }
                "--enable-rosout-logs" => out.rosout_logs = true,
                "--disable-rosout-logs" => out.rosout_logs = false,
                "--enable-stdout-logs" => out.stdout_logs = true,
                "--disable-stdout-logs" => out.stdout_logs = false,
                _ if IGNORED_WITH_VALUE.contains(&arg) => {
                    value(arg)?;
                }
                _ if IGNORED_FLAGS.contains(&arg) => {}
                _ => {
                    return Err(ArgsError::Unknown {
                        arg: arg.to_string(),
                    })
                }
            }
        }
        Ok(out)
    }

    fn add_remap(&mut self, flag: &str, rule: &str) -> Result<(), ArgsError> {
        let (node, from, to) = split_rule(flag, rule)?;
        if from.is_empty() || to.is_empty() {
            return Err(bad_rule(flag, rule, "both sides of `:=` must be names"));
        }
        match from {
            "__node" | "__name" => {
                check_base_name(to)?;
                self.node_renames.push((node, to.to_string()));
            }
            "__ns" => {
                let ns = if to.starts_with('/') {
                    to.to_string()
                } else {
                    format!("/{to}")
                };
                check_namespace(&ns)?;
                self.namespace_rules.push((node, ns));
            }
            _ => {
                check_topic_name(from)?;
                check_topic_name(to)?;
                self.remaps.push(Remap {
                    node,
                    from: from.to_string(),
                    to: to.to_string(),
                });
            }
        }
        Ok(())
    }

    /// The node's name: the last `__node` rule that applies to `default`
    /// (rules with a node prefix apply when it names the node as in code).
    pub fn node_name(&self, default: &str) -> String {
        self.node_renames
            .iter()
            .filter(|(node, _)| node.as_deref().is_none_or(|n| n == default))
            .map(|(_, name)| name.clone())
            .next_back()
            .unwrap_or_else(|| default.to_string())
    }

    /// The node's namespace (absolute, `/` when none is given).
    pub fn namespace(&self, default_node_name: &str) -> String {
        self.namespace_rules
            .iter()
            .filter(|(node, _)| node.as_deref().is_none_or(|n| n == default_node_name))
            .map(|(_, ns)| ns.clone())
            .next_back()
            .unwrap_or_else(|| "/".to_string())
    }

    /// Parameters given with `-p` for this node, in order (later ones win).
    pub fn params_for<'a>(
        &'a self,
        node_name: &'a str,
        default_node_name: &'a str,
    ) -> impl Iterator<Item = &'a ParamArg> + 'a {
        self.params.iter().filter(move |p| {
            p.node
                .as_deref()
                .is_none_or(|n| n == node_name || n == default_node_name)
        })
    }
}

fn bad_rule(flag: &str, rule: &str, reason: &str) -> ArgsError {
    ArgsError::BadRule {
        flag: flag.to_string(),
        rule: rule.to_string(),
        reason: reason.to_string(),
    }
}

/// `[node:]left:=right` → (node, left, right).
fn split_rule<'a>(
    flag: &str,
    rule: &'a str,
) -> Result<(Option<String>, &'a str, &'a str), ArgsError> {
    let (left, right) = rule
        .split_once(":=")
        .ok_or_else(|| bad_rule(flag, rule, "expected `name:=value`"))?;
    match left.split_once(':') {
        Some((node, name)) => {
            if node.is_empty() {
                return Err(bad_rule(flag, rule, "empty node name before `:`"));
            }
            Ok((Some(node.to_string()), name, right))
        }
        None => Ok((None, left, right)),
    }
}

fn valid_token(t: &str) -> bool {
    let mut chars = t.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !t.contains("__")
}

fn check_base_name(name: &str) -> Result<(), ArgsError> {
    if valid_token(name) {
        Ok(())
    } else {
        Err(ArgsError::BadName {
            name: name.to_string(),
            reason:
                "a node name is letters, digits and single underscores, not starting with a digit"
                    .into(),
        })
    }
}

fn check_namespace(ns: &str) -> Result<(), ArgsError> {
    if ns == "/" {
        return Ok(());
    }
    let bad = |reason: &str| {
        Err(ArgsError::BadName {
            name: ns.to_string(),
            reason: reason.to_string(),
        })
    };
    if ns.ends_with('/') {
        return bad("a namespace must not end with `/`");
    }
    if !ns[1..].split('/').all(valid_token) {
        return bad("each namespace token is letters, digits and single underscores, not starting with a digit");
    }
    Ok(())
}

/// A topic or service name as written: absolute (`/a/b`), relative (`a/b`)
/// or private (`~`, `~/a`).
fn check_topic_name(name: &str) -> Result<(), ArgsError> {
    let rest = if name == "~" {
        return Ok(());
    } else if let Some(r) = name.strip_prefix("~/") {
        r
    } else if let Some(r) = name.strip_prefix('/') {
        r
    } else {
        name
    };
    if rest.is_empty() || !rest.split('/').all(valid_token) {
        return Err(ArgsError::BadName {
            name: name.to_string(),
            reason:
                "each token is letters, digits and single underscores, not starting with a digit"
                    .into(),
        });
    }
    Ok(())
}

/// Resolves topic and service names of one node: `~` expansion, namespace,
/// then the first remapping rule that matches the fully qualified name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NameResolver {
    node: String,
    namespace: String,
    /// (resolved from, resolved to)
    remaps: Vec<(String, String)>,
}

impl NameResolver {
    /// `default_node` is the node's name as in code (for node-prefixed rules).
    pub fn new(args: &RosArgs, default_node: &str) -> Result<NameResolver, ArgsError> {
        let node = args.node_name(default_node);
        let namespace = args.namespace(default_node);
        check_base_name(&node)?;
        check_namespace(&namespace)?;
        let mut r = NameResolver {
            node,
            namespace,
            remaps: Vec::new(),
        };
        let mut remaps = Vec::new();
        for rule in &args.remaps {
            if rule
                .node
                .as_deref()
                .is_some_and(|n| n != default_node && n != r.node)
            {
                continue;
            }
            remaps.push((r.expand(&rule.from)?, r.expand(&rule.to)?));
        }
        r.remaps = remaps;
        Ok(r)
    }

    pub fn node_name(&self) -> &str {
        &self.node
    }

    pub fn namespace(&self) -> &str {
        &self.namespace
    }

    /// `/ns/node`.
    pub fn fully_qualified_node_name(&self) -> String {
        if self.namespace == "/" {
            format!("/{}", self.node)
        } else {
            format!("{}/{}", self.namespace, self.node)
        }
    }

    /// Expand `~` and make the name absolute (no remapping).
    pub fn expand(&self, name: &str) -> Result<String, ArgsError> {
        check_topic_name(name)?;
        let fqn = self.fully_qualified_node_name();
        Ok(if name == "~" {
            fqn
        } else if let Some(rest) = name.strip_prefix("~/") {
            format!("{fqn}/{rest}")
        } else if name.starts_with('/') {
            name.to_string()
        } else if self.namespace == "/" {
            format!("/{name}")
        } else {
            format!("{}/{name}", self.namespace)
        })
    }

    /// The fully qualified name after remapping.
    pub fn resolve(&self, name: &str) -> Result<String, ArgsError> {
        let expanded = self.expand(name)?;
        Ok(self
            .remaps
            .iter()
            .find(|(from, _)| *from == expanded)
            .map_or(expanded, |(_, to)| to.clone()))
    }
}

/// The DDS domain from the value of `ROS_DOMAIN_ID` (unset or empty: 0).
pub fn domain_id_from_env(value: Option<&str>) -> Result<u16, ArgsError> {
    match value.map(str::trim) {
        None | Some("") => Ok(0),
        Some(v) => match v.parse::<u16>() {
            Ok(d) if d <= 232 => Ok(d),
            _ => Err(ArgsError::BadDomainId {
                value: v.to_string(),
            }),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> RosArgs {
        RosArgs::parse(args).unwrap()
    }

    #[test]
    fn launch_style_arguments() {
        let a = parse(&[
            "--ros-args",
            "-r",
            "__node:=brake",
            "-r",
            "__ns:=/bench",
            "--params-file",
            "/tmp/p.yaml",
            "-r",
            "/joint_states:=/plate/joint_states",
            "-p",
            "simulation.rate_hz:=500.0",
            "--log-level",
            "WARN",
        ]);
        assert_eq!(a.node_name("annular_plate"), "brake");
        assert_eq!(a.namespace("annular_plate"), "/bench");
        assert_eq!(a.params_files, vec![PathBuf::from("/tmp/p.yaml")]);
        assert_eq!(
            a.params,
            vec![ParamArg {
                node: None,
                name: "simulation.rate_hz".into(),
                value: "500.0".into()
            }]
        );
        assert_eq!(a.log_level.as_deref(), Some("warn"));
        assert!(a.rosout_logs);
        let r = NameResolver::new(&a, "annular_plate").unwrap();
        assert_eq!(r.fully_qualified_node_name(), "/bench/brake");
        assert_eq!(r.resolve("/joint_states").unwrap(), "/plate/joint_states");
        assert_eq!(
            r.resolve("~/speed_command").unwrap(),
            "/bench/brake/speed_command"
        );
        assert_eq!(r.resolve("tf").unwrap(), "/bench/tf");
        assert_eq!(r.resolve("/tf").unwrap(), "/tf");
    }

    #[test]
    fn defaults_without_arguments() {
        let a = parse(&[]);
        assert_eq!(a.node_name("annular_plate"), "annular_plate");
        assert_eq!(a.namespace("annular_plate"), "/");
        let r = NameResolver::new(&a, "annular_plate").unwrap();
        assert_eq!(
            r.resolve("~/ale_1/wrench").unwrap(),
            "/annular_plate/ale_1/wrench"
        );
        assert_eq!(r.resolve("~").unwrap(), "/annular_plate");
        assert_eq!(r.resolve("clock").unwrap(), "/clock");
    }

    #[test]
    fn blocks_end_with_double_dash_and_may_repeat() {
        let a = parse(&[
            "--ros-args",
            "-r",
            "__node:=a",
            "--",
            "--ros-args",
            "--remap",
            "__name:=b",
        ]);
        assert_eq!(a.node_name("x"), "b");
        // Outside a block nothing is accepted.
        assert_eq!(
            RosArgs::parse(&["--ros-args", "-r", "__node:=a", "--", "stray"]),
            Err(ArgsError::Unknown {
                arg: "stray".into()
            })
        );
    }

    #[test]
    fn list_without_marker_is_one_block() {
        let a = parse(&["-p", "ros.frame_prefix:=left_", "--params-file", "x.yaml"]);
        assert_eq!(a.params[0].name, "ros.frame_prefix");
        assert_eq!(a.params[0].value, "left_");
        assert_eq!(a.params_files.len(), 1);
    }

    #[test]
    fn relative_remaps_resolve_in_the_namespace() {
        let a = parse(&[
            "--ros-args",
            "-r",
            "__ns:=/ns",
            "-r",
            "~/speed_command:=cmd",
            "-r",
            "joint_states:=/js",
        ]);
        let r = NameResolver::new(&a, "annular_plate").unwrap();
        assert_eq!(r.resolve("~/speed_command").unwrap(), "/ns/cmd");
        assert_eq!(r.resolve("joint_states").unwrap(), "/js");
        assert_eq!(r.resolve("/joint_states").unwrap(), "/joint_states");
    }

    #[test]
    fn node_prefixed_rules_apply_only_to_that_node() {
        let a = parse(&[
            "-r",
            "other:__node:=x",
            "-r",
            "annular_plate:__ns:=/mine",
            "-r",
            "other:/tf:=/tf2",
            "-p",
            "other:a:=1",
        ]);
        assert_eq!(a.node_name("annular_plate"), "annular_plate");
        assert_eq!(a.namespace("annular_plate"), "/mine");
        let r = NameResolver::new(&a, "annular_plate").unwrap();
        assert_eq!(r.resolve("/tf").unwrap(), "/tf");
        assert_eq!(a.params_for("annular_plate", "annular_plate").count(), 0);
        assert_eq!(a.params_for("other", "annular_plate").count(), 1);
    }

    #[test]
    fn relative_namespace_is_made_absolute() {
        let a = parse(&["-r", "__ns:=bench"]);
        assert_eq!(a.namespace("n"), "/bench");
    }

    #[test]
    fn errors_name_the_problem() {
        assert_eq!(
            RosArgs::parse(&["--ros-args", "-r"]),
            Err(ArgsError::MissingValue { flag: "-r".into() })
        );
        assert_eq!(
            RosArgs::parse(&["--ros-args", "--bogus"]),
            Err(ArgsError::Unknown {
                arg: "--bogus".into()
            })
        );
        assert!(matches!(
            RosArgs::parse(&["-r", "a=b"]),
            Err(ArgsError::BadRule { .. })
        ));
        assert!(matches!(
            RosArgs::parse(&["-r", "__node:=1abc"]),
            Err(ArgsError::BadName { .. })
        ));
        assert!(matches!(
            RosArgs::parse(&["-r", "__ns:=/a/"]),
            Err(ArgsError::BadName { .. })
        ));
        assert!(matches!(
            RosArgs::parse(&["-r", "/a/1b:=/c"]),
            Err(ArgsError::BadName { .. })
        ));
        assert!(matches!(
            RosArgs::parse(&["-p", ":=3"]),
            Err(ArgsError::BadRule { .. })
        ));
        let msg = RosArgs::parse(&["--ros-args", "--bogus"])
            .unwrap_err()
            .to_string();
        assert!(msg.contains("--bogus"), "{msg}");
    }

    #[test]
    fn ignored_and_logging_flags() {
        let a = parse(&[
            "--ros-args",
            "-e",
            "/enclave",
            "--log-level",
            "annular_plate:=debug",
            "--disable-rosout-logs",
            "--disable-stdout-logs",
            "--enable-external-lib-logs",
            "--log-file-name",
            "x",
        ]);
        assert_eq!(a.log_level.as_deref(), Some("debug"));
        assert!(!a.rosout_logs);
        assert!(!a.stdout_logs);
    }

    #[test]
    fn parameter_values_keep_their_text() {
        let a = parse(&[
            "-p",
            "plate.nodal_diameters:=[0, 1, 2]",
            "-p",
            "annular_plate:ros.publish_clock:=true",
        ]);
        assert_eq!(a.params[0].value, "[0, 1, 2]");
        assert_eq!(a.params[1].node.as_deref(), Some("annular_plate"));
        assert_eq!(a.params[1].name, "ros.publish_clock");
    }

    #[test]
    fn domain_id_rules() {
        assert_eq!(domain_id_from_env(None), Ok(0));
        assert_eq!(domain_id_from_env(Some("")), Ok(0));
        assert_eq!(domain_id_from_env(Some(" 42 ")), Ok(42));
        assert_eq!(domain_id_from_env(Some("232")), Ok(232));
        assert!(domain_id_from_env(Some("233")).is_err());
        assert!(domain_id_from_env(Some("-1")).is_err());
        assert!(domain_id_from_env(Some("abc")).is_err());
    }
}
