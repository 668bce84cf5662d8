//! The diagram as JSON: each point's parameter under the parameter's own name (`delta_a`, ...).

use super::{Branch, Diagram, Point, SpecialPoint};
use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Serialize, Serializer};

/// Serialises a value under a map key chosen at run time (the parameter's name).
struct Keyed<'a, T>(&'a str, &'a T);

impl Serialize for Keyed<'_, Point> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let p = self.1;
        let mut m = ser.serialize_map(Some(7))?;
        m.serialize_entry(self.0, &p.param)?;
        m.serialize_entry("alpha", &p.alpha)?;
        m.serialize_entry("beta", &p.beta)?;
        m.serialize_entry("p", &p.p)?;
        m.serialize_entry("q", &p.q)?;
        m.serialize_entry("r", &p.r)?;
        m.serialize_entry("stable", &p.stable)?;
        m.end()
    }
}

impl Serialize for Keyed<'_, Branch> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let mut m = ser.serialize_map(Some(1))?;
        m.serialize_entry("points", &Keyed(self.0, &self.1.points))?;
        m.end()
    }
}

impl Serialize for Keyed<'_, SpecialPoint> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let p = self.1;
        let mut m = ser.serialize_map(Some(7 + usize::from(p.frequency.is_some())))?;
        m.serialize_entry("kind", p.kind.name())?;
        m.serialize_entry(self.0, &p.param)?;
        m.serialize_entry("p", &p.p)?;
        m.serialize_entry("alpha", &p.alpha)?;
        m.serialize_entry("beta", &p.beta)?;
        m.serialize_entry("q", &p.q)?;
        m.serialize_entry("r", &p.r)?;
        if let Some(w) = p.frequency {
            m.serialize_entry("frequency", &w)?;
        }
        m.end()
    }
}

impl<T> Serialize for Keyed<'_, Vec<T>>
where
    for<'b> Keyed<'b, T>: Serialize,
{
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let mut seq = ser.serialize_seq(Some(self.1.len()))?;
        for item in self.1 {
            seq.serialize_element(&Keyed(self.0, item))?;
        }
        seq.end()
    }
}

impl Serialize for Diagram {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let key = self.parameter.as_str();
        let n = 4 + usize::from(!self.rudder_schedule.is_empty());
        let mut m = ser.serialize_map(Some(n))?;
        m.serialize_entry("aircraft", &self.aircraft)?;
        m.serialize_entry("parameter", &self.parameter)?;
        m.serialize_entry("branches", &Keyed(key, &self.branches))?;
        m.serialize_entry("special_points", &Keyed(key, &self.special_points))?;
        if !self.rudder_schedule.is_empty() {
            m.serialize_entry("rudder_schedule", &self.rudder_schedule)?;
        }
        m.end()
    }
}
