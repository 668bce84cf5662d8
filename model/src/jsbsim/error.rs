//! The error of reading a JSBSim model: the file, the line, the element and what was expected.

use std::fmt;

/// Why a JSBSim model could not be read or evaluated. The message names the file, the line (1-based,
/// 0 when the problem is not at one place in the file), the element and what was expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JsbsimError {
    /// The file as given (path or catalogue name).
    pub file: String,
    /// 1-based line of the element, 0 when not tied to one line.
    pub line: u32,
    /// The element (or property) concerned.
    pub element: String,
    /// What is wrong and what was expected.
    pub message: String,
}

impl JsbsimError {
    /// An error at `line` of `file` about `element`.
    pub fn new(file: &str, line: u32, element: &str, message: impl Into<String>) -> JsbsimError {
        JsbsimError {
            file: file.to_string(),
            line,
            element: element.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for JsbsimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(
                f,
                "{}:{}: <{}>: {}",
                self.file, self.line, self.element, self.message
            )
        } else {
            write!(f, "{}: {}: {}", self.file, self.element, self.message)
        }
    }
}

impl std::error::Error for JsbsimError {}
