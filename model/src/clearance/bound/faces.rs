//! The faces of a lifted box lifted so far, kept with it ([`Faces`]) and taken from there
//! ([`BoxPolys::face`]).

use super::{BoxPolys, LiftedBox};
use crate::interval::I;
use std::sync::Arc;

/// The last few faces of a lifted box that were lifted ([`BoxPolys::face`]): the face where
/// J or |delta_a| comes closest to zero is set by the signs of their gradients, which rarely
/// change from one slab of roll rates to the next, and lifting a box costs more than the chain
/// on it. A lifted box is a pure function of its box and side, so a face taken from here is
/// the one lifting it again would give.
#[derive(Debug, Default)]
pub(super) struct Faces(std::sync::Mutex<Vec<Arc<LiftedBox>>>);

/// How many faces of a lifted box [`Faces`] keeps (each as large as the box lifted): J's face
/// and the aileron's alternate, and either moves when a gradient's sign flips. On the F-104's
/// 15-coefficient box four instead of two halve the faces lifted (603 instead of 1,297 of the
/// 8,071 asked for) at the same peak memory.
const FACES: usize = 4;

impl Clone for Faces {
    /// None: a clone is lifted data shared no further.
    fn clone(&self) -> Self {
        Faces::default()
    }
}

impl BoxPolys {
    /// [`BoxPolys::lift_part`] of the face `theta` of `whole`, taken from the faces of `whole`
    /// lifted so far when it is one of them.
    pub(super) fn face(&self, theta: &[I], whole: &LiftedBox) -> Arc<LiftedBox> {
        let lock = || whole.faces.0.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(f) = lock().iter().find(|f| f.theta == theta) {
            return Arc::clone(f);
        }
        let f = Arc::new(self.lift_part(theta, whole));
        let mut faces = lock();
        faces.insert(0, Arc::clone(&f));
        faces.truncate(FACES);
        f
    }
}
