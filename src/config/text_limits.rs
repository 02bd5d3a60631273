//! Limits checked before a parameter file is parsed, so that any input is
//! accepted or refused in well under a second: its size, and how deeply its
//! YAML nests (the YAML parser's time grows with the square of the depth).
//!
//! A ROS 2 parameter file needs four levels (node, `ros__parameters`,
//! section, key) and flat arrays; nested maps for dotted names add a few.

use super::ConfigError;

/// Largest parameter file, bytes (the shipped scenes are 2–4 kB).
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Deepest nesting of maps and lists accepted.
pub const MAX_DEPTH: usize = 32;

/// Refuse text whose nesting goes deeper than [`MAX_DEPTH`], naming the line.
/// Counts block indentation levels, `- ` sequence markers and flow brackets
/// outside strings and comments, in one pass over the text.
pub fn check_depth(text: &str) -> Result<(), ConfigError> {
    let mut indents: Vec<usize> = Vec::new();
    let mut flow = 0usize;
    for (number, line) in text.lines().enumerate() {
        let content = line.trim_start_matches(' ');
        if flow == 0 && !content.is_empty() && !content.starts_with('#') {
            let indent = line.len() - content.len();
            while indents.last().is_some_and(|&i| i >= indent) {
                indents.pop();
            }
            indents.push(indent);
        }
        let mut dashes = 0;
        let mut rest = content;
        while let Some(r) = rest.strip_prefix("- ") {
            dashes += 1;
            rest = r.trim_start_matches(' ');
        }
        let deepest = indents.len() + dashes + flow_depth(rest, &mut flow);
        if deepest > MAX_DEPTH {
            return Err(ConfigError::TooDeep {
                line: number + 1,
                limit: MAX_DEPTH,
            });
        }
    }
    Ok(())
}

/// Track `[`/`{` nesting through one line (strings and comments skipped);
/// returns the deepest flow level reached on it.
fn flow_depth(line: &str, flow: &mut usize) -> usize {
    let mut deepest = *flow;
    let mut quote: Option<char> = None;
    let mut escaped = false;
    let mut previous = ' ';
    for c in line.chars() {
        match quote {
            Some('"') if escaped => escaped = false,
            Some('"') if c == '\\' => escaped = true,
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None => match c {
                '"' | '\'' => quote = Some(c),
                '#' if previous.is_whitespace() => break,
                '[' | '{' => {
                    *flow += 1;
                    deepest = deepest.max(*flow);
                }
                ']' | '}' => *flow = flow.saturating_sub(1),
                _ => {}
            },
        }
        previous = c;
    }
    deepest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_file_passes_and_deep_nesting_is_refused_with_its_line() {
        let scene = "annular_plate:\n  ros__parameters:\n    plate:\n      damping: [0.02]  # [[[ in a comment\n      note: \"[[[[\"\n";
        assert_eq!(check_depth(scene), Ok(()));
        let deep = format!(
            "annular_plate:\n  ros__parameters:\n    plate:\n      damping: {}{}\n",
            "[".repeat(40),
            "]".repeat(40)
        );
        assert_eq!(
            check_depth(&deep),
            Err(ConfigError::TooDeep {
                line: 4,
                limit: MAX_DEPTH
            })
        );
        let mut block = String::new();
        for level in 0..40 {
            block.push_str(&format!("{}k{level}:\n", " ".repeat(level)));
        }
        assert!(
            matches!(
                check_depth(&block),
                Err(ConfigError::TooDeep { line: 33, .. })
            ),
            "{:?}",
            check_depth(&block)
        );
        let dashes = format!("a:\n  {}x\n", "- ".repeat(40));
        assert!(matches!(
            check_depth(&dashes),
            Err(ConfigError::TooDeep { line: 2, .. })
        ));
    }
}
