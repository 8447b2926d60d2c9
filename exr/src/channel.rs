//! Channel names of the layout: `S0.<λ>nm` (emissive; `S1`–`S3` the
//! other Stokes components), `T.<λ>nm` (reflective), a wavelength with a
//! comma as decimal mark, in metres with an SI prefix or in hertz.

use crate::ExrError;

/// What a spectral channel holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Component {
    /// Stokes component 0, 1, 2 or 3 of emitted radiance (`S0` is the
    /// radiance).
    Stokes(u8),
    /// A reflective (or transmissive) ratio.
    Reflective,
}

/// The speed of light, m/s (for wavelengths given as frequencies).
const LIGHT_SPEED: f64 = 299_792_458.0;

/// The channel's name for `lambda` nm: `S0.374,688nm`, `T.550nm` (the
/// shortest decimal that reads back as the same `f64`).
#[must_use]
pub fn name(component: Component, lambda: f64) -> String {
    let prefix = match component {
        Component::Stokes(i) => format!("S{i}"),
        Component::Reflective => "T".into(),
    };
    format!("{prefix}.{}nm", format!("{lambda}").replace('.', ","))
}

/// A channel's component and wavelength (nm); `Ok(None)` for a channel
/// outside the layout (`R`, `G`, `B`, `A`, anything not starting with
/// `S0.`–`S3.` or `T.`); an [`ExrError::ChannelName`] for a name that
/// starts as one and does not follow the grammar.
pub fn parse(name: &str) -> Result<Option<(Component, f64)>, ExrError> {
    let (component, rest) = if let Some(rest) = name.strip_prefix("T.") {
        (Component::Reflective, rest)
    } else {
        match name.as_bytes() {
            [b'S', d @ b'0'..=b'3', b'.', ..] => (Component::Stokes(d - b'0'), &name[3..]),
            _ => return Ok(None),
        }
    };
    let bad = |why: &str| ExrError::ChannelName { name: name.into(), why: why.into() };
    if component == Component::Reflective && rest.contains('.') {
        return Err(bad("bispectral channels (T.<λ>.<λ>) are not supported"));
    }
    let (number, unit) = rest.split_at(number_length(rest));
    if unit.starts_with('.') {
        return Err(bad("a comma as decimal mark (374,688nm), found a point"));
    }
    if number.is_empty() {
        return Err(bad("a number such as 374,688 before the unit"));
    }
    if unit.is_empty() {
        return Err(bad("a wavelength with a unit (nm, um, m, Hz, …)"));
    }
    let value: f64 = number.replace(',', ".").parse().map_err(|_| bad("a number such as 374,688"))?;
    let nm = to_nm(value, unit).ok_or_else(|| bad("a unit of m with an SI prefix (nm, um, …) or Hz"))?;
    if !(nm.is_finite() && nm > 0.0) {
        return Err(bad("a positive, finite wavelength"));
    }
    Ok(Some((component, nm)))
}

/// The length of the number that opens `s`, by the layout's grammar:
/// digits, a comma and digits, then an exponent (`e` or `E`, a sign,
/// digits) only where digits follow, so that `E` before a unit is the exa
/// prefix (`5,5e-25Em` is 5.5·10⁻²⁵ Em). 0 if `s` opens with no digit.
fn number_length(s: &str) -> usize {
    let b = s.as_bytes();
    let digits = |from: usize| b[from..].iter().take_while(|c| c.is_ascii_digit()).count();
    let mut end = digits(0);
    if end == 0 {
        return 0;
    }
    if b.get(end) == Some(&b',') && digits(end + 1) > 0 {
        end += 1 + digits(end + 1);
    }
    if matches!(b.get(end), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(b.get(end + 1), Some(b'+' | b'-')));
        let exponent = digits(end + 1 + sign);
        if exponent > 0 {
            end += 1 + sign + exponent;
        }
    }
    end
}

/// `value` in `unit` as nanometres: metres with an SI prefix, or hertz.
fn to_nm(value: f64, unit: &str) -> Option<f64> {
    const PREFIXES: [(&str, f64); 21] = [
        ("Y", 1e24),
        ("Z", 1e21),
        ("E", 1e18),
        ("P", 1e15),
        ("T", 1e12),
        ("G", 1e9),
        ("M", 1e6),
        ("k", 1e3),
        ("h", 1e2),
        ("da", 1e1),
        ("", 1.0),
        ("d", 1e-1),
        ("c", 1e-2),
        ("m", 1e-3),
        ("u", 1e-6),
        ("n", 1e-9),
        ("p", 1e-12),
        ("f", 1e-15),
        ("a", 1e-18),
        ("z", 1e-21),
        ("y", 1e-24),
    ];
    if unit == "nm" {
        return Some(value);
    }
    let (base, hertz) = match unit.strip_suffix("Hz") {
        Some(prefix) => (prefix, true),
        None => (unit.strip_suffix('m')?, false),
    };
    let scale = PREFIXES.iter().find(|(p, _)| *p == base)?.1;
    let si = value * scale;
    Some(if hertz { LIGHT_SPEED / si * 1e9 } else { si * 1e9 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_back_and_follow_other_writers() {
        for lambda in [380.0, 374.688, 555.5, 729.999_999_9] {
            for c in [Component::Stokes(0), Component::Reflective] {
                assert_eq!(parse(&name(c, lambda)).unwrap(), Some((c, lambda)));
            }
        }
        assert_eq!(name(Component::Stokes(0), 374.688), "S0.374,688nm");
        assert_eq!(parse("S0.374,688nm").unwrap(), Some((Component::Stokes(0), 374.688)));
        assert_eq!(parse("S3.500nm").unwrap(), Some((Component::Stokes(3), 500.0)));
        assert_eq!(parse("T.0,55um").unwrap(), Some((Component::Reflective, 550.0)));
        assert_eq!(parse("T.5,5e-7m").unwrap(), Some((Component::Reflective, 550.0)));
        let hz = parse("S0.545077,196363636GHz").unwrap().unwrap().1;
        assert!((hz - 550.0).abs() < 1e-9, "{hz}");
        for other in ["R", "G", "B", "A", "S4.500nm", "S0", "Y", "T"] {
            assert_eq!(parse(other).unwrap(), None, "{other}");
        }
    }

    #[test]
    fn malformed_names_say_what_is_wrong() {
        for (bad, why) in [
            ("S0.374.688nm", "comma"),
            ("S0.nm", "number"),
            ("S0.500", "unit"),
            ("S0.500furlongs", "unit of m"),
            ("S0.0nm", "positive"),
            ("T.500nm.600nm", "bispectral"),
            ("S0.5,0,0nm", "unit"),
            ("S0.,5nm", "number"),
            ("S0.5,nm", "unit"),
        ] {
            let e = parse(bad).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains(why), "{bad}: {e}");
        }
    }

    /// 550 nm written with every SI prefix of the metre and of the hertz
    /// (exa's `E` read as the prefix, not an exponent), with and without
    /// an exponent.
    #[test]
    fn every_si_prefix_reads() {
        let prefixes = [
            ("Y", 24),
            ("Z", 21),
            ("E", 18),
            ("P", 15),
            ("T", 12),
            ("G", 9),
            ("M", 6),
            ("k", 3),
            ("h", 2),
            ("da", 1),
            ("", 0),
            ("d", -1),
            ("c", -2),
            ("m", -3),
            ("u", -6),
            ("n", -9),
            ("p", -12),
            ("f", -15),
            ("a", -18),
            ("z", -21),
            ("y", -24),
        ];
        let hertz = LIGHT_SPEED / 550e-9;
        for (prefix, power) in prefixes {
            for exponent in ["e", "E"] {
                let metres = format!("T.5,5{exponent}{}{prefix}m", -7 - power);
                let got = parse(&metres).unwrap().unwrap().1;
                assert!((got / 550.0 - 1.0).abs() < 1e-12, "{metres}: {got}");
                let frequency = format!(
                    "S0.{}{exponent}{}{prefix}Hz",
                    format!("{:.12}", hertz / 1e14).replace('.', ","),
                    14 - power
                );
                let got = parse(&frequency).unwrap().unwrap().1;
                assert!((got / 550.0 - 1.0).abs() < 1e-12, "{frequency}: {got}");
            }
        }
        assert_eq!(parse("T.5,5e-25Em").unwrap(), Some((Component::Reflective, 5.5e-25 * 1e18 * 1e9)));
        assert_eq!(parse("T.1Em").unwrap().unwrap().1, 1e27, "E alone is exa");
        assert_eq!(parse("T.5,5E+2nm").unwrap().unwrap().1, 550.0);
        assert!(parse("T.5E+m").unwrap_err().to_string().contains("unit of m"), "E+ without digits");
    }
}
