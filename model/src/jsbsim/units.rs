//! The units a JSBSim model may write on `<metrics>`, `<mass_balance>` and `<propulsion>` values,
//! converted to the units JSBSim computes in (ft, ft^2, lbs, slug ft^2, inches for locations).
//! The factors are those of JSBSim's unit table (so that the mass and the forces agree with
//! JSBSim's own to rounding); the exact SI factors are used only where this crate writes SI.

/// Feet per metre in JSBSim's unit table.
pub const FT_PER_M: f64 = 3.2808399;
/// Slug ft^2 per kg m^2 in JSBSim's unit table.
const SLUGFT2_PER_KGM2: f64 = 1.0 / 1.35594;
/// Pounds per kilogram in JSBSim's unit table.
const LBS_PER_KG: f64 = 1.0 / 0.45359237;
/// Slugs per pound (JSBSim's `lbtoslug`, 1/32.174049).
pub const SLUG_PER_LB: f64 = 1.0 / 32.174049;
/// Kilograms per slug (exact SI: 0.45359237 kg/lb times 32.174049 lb/slug).
pub const KG_PER_SLUG: f64 = 0.45359237 * 32.174049;
/// Metres per foot (exact).
pub const M_PER_FT: f64 = 0.3048;

/// The kind of quantity an element holds, which fixes the units it accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// A length, converted to ft.
    Length,
    /// A location coordinate, converted to inches (JSBSim's structural frame).
    Location,
    /// An area, converted to ft^2.
    Area,
    /// A moment or product of inertia, converted to slug ft^2.
    Inertia,
    /// A weight, converted to lbs.
    Weight,
    /// An angle, converted to rad.
    Angle,
}

impl Quantity {
    /// The units accepted, for messages.
    pub fn accepted(self) -> &'static str {
        match self {
            Quantity::Length | Quantity::Location => "FT, IN, M, CM or KM",
            Quantity::Area => "FT2, IN2, M2 or CM2",
            Quantity::Inertia => "SLUG*FT2 or KG*M2",
            Quantity::Weight => "LBS or KG",
            Quantity::Angle => "RAD or DEG",
        }
    }

    /// The factor that takes a value in `unit` to this quantity's working unit; an empty unit is
    /// the working unit itself (as in JSBSim). `None` for a unit this quantity does not accept.
    pub fn factor(self, unit: &str) -> Option<f64> {
        let ft = match unit {
            "FT" => Some(1.0),
            "IN" => Some(1.0 / 12.0),
            "M" => Some(FT_PER_M),
            "CM" => Some(0.032808399),
            "KM" => Some(3280.8399),
            _ => None,
        };
        match self {
            Quantity::Length if unit.is_empty() => Some(1.0),
            Quantity::Length => ft,
            Quantity::Location if unit.is_empty() => Some(1.0),
            Quantity::Location => ft.map(|f| f * 12.0),
            Quantity::Area => match unit {
                "" | "FT2" => Some(1.0),
                "IN2" => Some(1.0 / 144.0),
                "M2" => Some(FT_PER_M * FT_PER_M),
                "CM2" => Some(0.032808399 * 0.032808399),
                _ => None,
            },
            Quantity::Inertia => match unit {
                "" | "SLUG*FT2" => Some(1.0),
                "KG*M2" => Some(SLUGFT2_PER_KGM2),
                _ => None,
            },
            Quantity::Weight => match unit {
                "" | "LBS" => Some(1.0),
                "KG" => Some(LBS_PER_KG),
                _ => None,
            },
            Quantity::Angle => match unit {
                "" | "RAD" => Some(1.0),
                "DEG" => Some(std::f64::consts::PI / 180.0),
                _ => None,
            },
        }
    }
}
