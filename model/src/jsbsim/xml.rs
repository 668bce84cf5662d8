//! Reading values out of a JSBSim XML document: numbers with their `unit` attribute, locations
//! (`<x>`, `<y>`, `<z>`), child elements by name, each failure naming the file, line and element.

use super::error::JsbsimError;
use super::units::Quantity;
use roxmltree::Node;

/// The file being read (for messages) and its parsed document.
#[derive(Clone, Copy)]
pub struct Source<'a> {
    /// The file name used in messages.
    pub file: &'a str,
}

impl Source<'_> {
    /// The 1-based line where `node` starts.
    pub fn line(&self, node: Node) -> u32 {
        node.document().text_pos_at(node.range().start).row
    }

    /// An error at `node`.
    pub fn error(&self, node: Node, message: impl Into<String>) -> JsbsimError {
        JsbsimError::new(self.file, self.line(node), node.tag_name().name(), message)
    }

    /// The number that is the whole text of `node`.
    pub fn number(&self, node: Node) -> Result<f64, JsbsimError> {
        let text = text(node);
        let text = text.trim();
        parse_number(text)
            .ok_or_else(|| self.error(node, format!("`{text}` is not a number (expected one)")))
    }

    /// The number of `node` converted by its `unit` attribute to `quantity`'s working unit.
    pub fn quantity(&self, node: Node, quantity: Quantity) -> Result<f64, JsbsimError> {
        let unit = node.attribute("unit").unwrap_or("").trim();
        let factor = quantity.factor(unit).ok_or_else(|| {
            self.error(
                node,
                format!(
                    "unit `{unit}` not understood (expected {})",
                    quantity.accepted()
                ),
            )
        })?;
        Ok(self.number(node)? * factor)
    }

    /// The optional child `name` of `node` as a `quantity`.
    pub fn child_quantity(
        &self,
        node: Node,
        name: &str,
        quantity: Quantity,
    ) -> Result<Option<f64>, JsbsimError> {
        child(node, name)
            .map(|c| self.quantity(c, quantity))
            .transpose()
    }

    /// A `<location>`-like element (children `x`, `y`, `z`, a `unit` on the element) in inches
    /// of JSBSim's structural frame (x aft, y right, z up). A missing coordinate is zero.
    pub fn location(&self, node: Node) -> Result<[f64; 3], JsbsimError> {
        let unit = node.attribute("unit").unwrap_or("").trim();
        let factor = Quantity::Location.factor(unit).ok_or_else(|| {
            self.error(
                node,
                format!(
                    "unit `{unit}` not understood (expected {})",
                    Quantity::Location.accepted()
                ),
            )
        })?;
        let mut xyz = [0.0; 3];
        for (k, name) in ["x", "y", "z"].iter().enumerate() {
            if let Some(c) = child(node, name) {
                xyz[k] = self.number(c)? * factor;
            }
        }
        Ok(xyz)
    }
}

/// The text of `node` without its comments (every text child joined).
pub fn text(node: Node) -> String {
    node.children()
        .filter(|c| c.is_text())
        .filter_map(|c| c.text())
        .collect()
}

/// The first child element of `node` named `name`.
pub fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// The child elements of `node` named `name`.
pub fn children<'a, 'i: 'a>(
    node: Node<'a, 'i>,
    name: &'a str,
) -> impl Iterator<Item = Node<'a, 'i>> + 'a {
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

/// A decimal number as JSBSim's data files write them (`1.5`, `-2e-3`, `+.5`); `None` otherwise.
pub fn parse_number(text: &str) -> Option<f64> {
    let v: f64 = text.parse().ok()?;
    v.is_finite().then_some(v)
}
