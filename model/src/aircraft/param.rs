//! The twenty parameters of the PSS model (Appendix A.2): the inertia coefficients C, D, E, the
//! fifteen dimensional derivatives and the two quantities of the trim the model is linearized
//! about (its lift and the angle of attack of the principal axis), with their TOML keys, units and
//! symbols.

/// The twenty parameters of the PSS model (Appendix A.2, extended by the trim), in the paper's
/// notation.
///
/// The order is the order of the fields of the generated `Derivatives` struct and of the
/// TOML keys in error messages; it never changes silently.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Param {
    /// Inertia coupling coefficient in pitch, C = (Iz - Ix)/Iy.
    C,
    /// Inertia coupling coefficient in yaw, D = (Iy - Ix)/Iz.
    D,
    /// Inertia coupling coefficient in roll, E = (Iz - Iy)/Ix.
    E,
    /// z_alpha, 1/s.
    ZAlpha,
    /// y_beta, 1/s.
    YBeta,
    /// l_p, 1/s.
    Lp,
    /// l_r, 1/s.
    Lr,
    /// l_beta, 1/s^2.
    LBeta,
    /// l_delta_a, 1/s^2.
    LDeltaA,
    /// m_q, 1/s.
    Mq,
    /// m_alpha, 1/s^2.
    MAlpha,
    /// m_delta_e, 1/s^2.
    MDeltaE,
    /// n_p, 1/s.
    Np,
    /// n_r, 1/s.
    Nr,
    /// n_beta, 1/s^2.
    NBeta,
    /// n_delta_a, 1/s^2.
    NDeltaA,
    /// n_delta_r, 1/s^2.
    NDeltaR,
    /// l_delta_r, 1/s^2 (roll due to rudder; optional, default 0).
    LDeltaR,
    /// z_0, rad/s: the lift of the trim the derivatives are taken at, `Z_0 / (m V) = -n g / V`
    /// for a load factor n (optional, default 0: the paper's aircraft, whose angles are measured
    /// from zero lift).
    Z0,
    /// alpha_t, rad: the angle of attack of the principal x-axis at that trim, which rolling
    /// about the principal axis turns into sideslip (optional, default 0: the paper's aircraft,
    /// whose principal axis lies on the flight path at zero lift).
    AlphaT,
}

impl Param {
    /// How many parameters there are.
    pub const COUNT: usize = 20;

    /// All parameters in their fixed order.
    pub const ALL: [Param; Param::COUNT] = [
        Param::C,
        Param::D,
        Param::E,
        Param::ZAlpha,
        Param::YBeta,
        Param::Lp,
        Param::Lr,
        Param::LBeta,
        Param::LDeltaA,
        Param::Mq,
        Param::MAlpha,
        Param::MDeltaE,
        Param::Np,
        Param::Nr,
        Param::NBeta,
        Param::NDeltaA,
        Param::NDeltaR,
        Param::LDeltaR,
        Param::Z0,
        Param::AlphaT,
    ];

    /// Snake-case name: the TOML key (`[derivatives]` or `[inertia]`) and the Rust field name.
    pub fn key(self) -> &'static str {
        match self {
            Param::C => "C",
            Param::D => "D",
            Param::E => "E",
            Param::ZAlpha => "z_alpha",
            Param::YBeta => "y_beta",
            Param::Lp => "l_p",
            Param::Lr => "l_r",
            Param::LBeta => "l_beta",
            Param::LDeltaA => "l_delta_a",
            Param::Mq => "m_q",
            Param::MAlpha => "m_alpha",
            Param::MDeltaE => "m_delta_e",
            Param::Np => "n_p",
            Param::Nr => "n_r",
            Param::NBeta => "n_beta",
            Param::NDeltaA => "n_delta_a",
            Param::NDeltaR => "n_delta_r",
            Param::LDeltaR => "l_delta_r",
            Param::Z0 => "z_0",
            Param::AlphaT => "alpha_t",
        }
    }

    /// LaTeX symbol as printed in the paper.
    pub fn latex(self) -> &'static str {
        match self {
            Param::C => "C",
            Param::D => "D",
            Param::E => "E",
            Param::ZAlpha => "z_\\alpha",
            Param::YBeta => "y_\\beta",
            Param::Lp => "l_p",
            Param::Lr => "l_r",
            Param::LBeta => "l_\\beta",
            Param::LDeltaA => "l_{\\delta a}",
            Param::Mq => "m_q",
            Param::MAlpha => "m_\\alpha",
            Param::MDeltaE => "m_{\\delta e}",
            Param::Np => "n_p",
            Param::Nr => "n_r",
            Param::NBeta => "n_\\beta",
            Param::NDeltaA => "n_{\\delta a}",
            Param::NDeltaR => "n_{\\delta r}",
            Param::LDeltaR => "l_{\\delta r}",
            Param::Z0 => "z_0",
            Param::AlphaT => "\\alpha_t",
        }
    }

    /// Unit of the parameter, for documentation.
    pub fn unit(self) -> &'static str {
        match self {
            Param::C | Param::D | Param::E => "1",
            Param::ZAlpha | Param::YBeta | Param::Lp | Param::Lr | Param::Mq | Param::Np => "1/s",
            Param::Nr => "1/s",
            Param::Z0 => "rad/s",
            Param::AlphaT => "rad",
            _ => "1/s^2",
        }
    }

    /// Position in [`Param::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }
}
