//! The input-deck fragments of `examples/decks/` (docs/input-decks.md): the keyword lines that
//! make Abaqus or CalculiX call the library's entry points, with `PROPS` data lines rendered from
//! the laws' layouts (`interfacial::props::schema`, through the named-setter builders), eight
//! values a line as Abaqus reads them, and a comment line per entry from the layout's own
//! description. The committed fragments must be exactly what this file renders;
//! `INTERFACIAL_BLESS=1 cargo test --test decks` rewrites them.
//!
//! Each committed fragment is then read back as a solver would read it (keyword lines, their
//! parameters, the data lines after them; comments skipped) and checked by the library itself:
//! the `PROPS` by the checked parser (`friction_law_checked`, the one that names the entry) and
//! by `ifl_props_check` (the C API a pre-processor asks), the
//! number of data values against `PROPERTIES=`, and one call of the entry point the fragment
//! selects, which must not be refused: FRIC and UINTER one increment with `NSTATV = DEPVAR` and
//! the deck's interaction name (UINTER's normal stress K_n·h), FRIC_COEF one point (μ against
//! its closed form), VFRIC one point (the force μ·F_N); GAPCON's interaction must have a law in
//! the example configuration file.

use std::ffi::{CStr, CString, c_char, c_int};
use std::path::Path;

#[path = "common/fric_coef.rs"]
mod fric_coef_common;
#[path = "common/vfric.rs"]
mod vfric_common;

use interfacial::abi::{IflStatus, ifl_clear_error, ifl_props_check};
use interfacial::config::Config;
use interfacial::props::schema::Layout;
use interfacial::props::{
    ADHESIVE, AdhesiveBuilder, COULOMB, CoulombBuilder, FrictionLaw, RATE_STATE, RateStateBuilder,
    friction_law_checked,
};
use interfacial_test_hosts::{FricCall, UinterCall};

/// The folder of the fragments.
const DECKS: &str = "examples/decks";

/// The example configuration file the GAPCON fragments name (hand-written; checked below).
const CONFIG: &str = "interfacial.toml";

/// Which entry point a fragment makes the solver call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Routine {
    /// `*FRICTION, USER`: FRIC (Abaqus/Standard).
    Fric,
    /// `*FRICTION, USER=COEFFICIENT`: FRIC_COEF (Abaqus/Standard).
    FricCoef,
    /// `*FRICTION, USER` in Abaqus/Explicit: VFRIC.
    Vfric,
    /// `*SURFACE INTERACTION, USER`: UINTER (Abaqus/Standard).
    Uinter,
    /// `*GAP CONDUCTANCE, USER`: GAPCON (Abaqus/Standard).
    Gapcon,
    /// `*GAP CONDUCTANCE, USER`: CalculiX's gapcon.
    GapconCalculix,
}

/// One fragment.
struct Deck {
    file: &'static str,
    title: &'static str,
    routine: Routine,
    interaction: &'static str,
    /// `DEPVAR=` (the law's `NSTATV`), when the routine has state variables.
    depvar: Option<usize>,
    /// The layout and the `PROPS` values (`NPROPS` = their number).
    props: Option<(&'static Layout, Vec<f64>)>,
    /// Comment lines after the header: what else the model needs.
    notes: &'static [&'static str],
}

fn decks() -> Vec<Deck> {
    // Law 1's exponential decay, through FRIC and through FRIC_COEF.
    let decay = CoulombBuilder::new()
        .mu(0.6)
        .mu_law(1.0)
        .mu_k(0.3)
        .decay(4.0)
        .build_first(10);
    // Law 2's friction (mu_d = 0.3, mu_s = 0.6, S_a = 5, gamma_crit = 1e-3), through FRIC and,
    // with separation adhesion and a normal stiffness, through UINTER.
    let adhesive = AdhesiveBuilder::new()
        .coeff(0.3)
        .coeff_static(0.6)
        .sa(5.0)
        .gamma_crit(1e-3);
    vec![
        Deck {
            file: "abaqus_fric_coulomb.inp",
            title: "Coulomb friction with elastic stick through FRIC (Abaqus/Standard)",
            routine: Routine::Fric,
            interaction: "SI_COULOMB",
            depvar: Some(3),
            props: Some((
                &COULOMB,
                CoulombBuilder::new()
                    .mu(0.3)
                    .slip_tolerance(0.005)
                    .build_first(7),
            )),
            notes: &[
                "Law 1 (docs/props.md): mu = 0.3, tau_max none, gamma_crit = 0.005 x CHRLNGTH,",
                "elastic stick. NSTATV = DEPVAR >= 3 (accumulated slip, slip rate, stick or slip).",
            ],
        },
        Deck {
            file: "abaqus_fric_decay.inp",
            title: "rate-dependent Coulomb friction (exponential decay) through FRIC",
            routine: Routine::Fric,
            interaction: "SI_DECAY",
            depvar: Some(3),
            props: Some((&COULOMB, decay.clone())),
            notes: &[
                "Law 1 with mu = mu_k + (mu_s - mu_k) exp(-d_c v): mu_s = 0.6, mu_k = 0.3, d_c = 4;",
                "PROPS(11..20) left out (PROPERTIES=10): they take their documented defaults.",
                "The tangent is unsymmetric: run the step with *STEP, UNSYMM=YES.",
            ],
        },
        Deck {
            file: "abaqus_fric_adhesive.inp",
            title: "adhesive friction (law 2) through FRIC",
            routine: Routine::Fric,
            interaction: "SI_ADHESIVE_FRIC",
            depvar: Some(3),
            props: Some((
                &ADHESIVE,
                adhesive.clone().kmu(0.05).vhalf(0.1).build_first(8),
            )),
            notes: &[
                "Law 2 (docs/props.md): mu_d = 0.3, mu_s = 0.6, S_a = 5, k_mu = 0.05, v_half = 0.1,",
                "gamma_crit = 1e-3. FRIC is called for closed points only, so N_a plays no part.",
            ],
        },
        Deck {
            file: "abaqus_fric_rate_state.inp",
            title: "rate-and-state friction (law 3) through FRIC",
            routine: Routine::Fric,
            interaction: "SI_RATE_STATE",
            depvar: Some(4),
            props: Some((
                &RATE_STATE,
                RateStateBuilder::new()
                    .mu0(0.6)
                    .a(0.01)
                    .b(0.015)
                    .v0(1e-6)
                    .l(1e-5)
                    .form(1.0)
                    .slip_tolerance(0.005)
                    .build(),
            )),
            notes: &[
                "Law 3 (docs/props.md): mu0 = 0.6 at V0 = 1e-6, a = 0.01, b = 0.015 (b > a:",
                "velocity weakening), L = 1e-5; aging law, regularised mu (finite as V -> 0);",
                "gamma_crit = 0.005 x CHRLNGTH; theta starts at L/V0. NSTATV = DEPVAR >= 4",
                "(STATEV(4) keeps the state theta). V0 and L in the model's velocity and length.",
            ],
        },
        Deck {
            file: "abaqus_uinter_adhesive.inp",
            title: "the whole adhesive interface through UINTER (Abaqus/Standard)",
            routine: Routine::Uinter,
            interaction: "SI_ADHESIVE",
            depvar: Some(3),
            props: Some((
                &ADHESIVE,
                adhesive.na(10.0).normal_stiffness(1e6).build_first(10),
            )),
            notes: &[
                "Law 2 with separation adhesion (N_a = 10) and the penalty normal stiffness",
                "K_n = 1e6 that UINTER needs (docs/uinter.md). No *SURFACE BEHAVIOR or *FRICTION",
                "under this interaction: UINTER defines both. PROPS(11) = 1 would add gap",
                "conduction from INTERFACIAL_CONFIG (the GAPCON law of this interaction).",
            ],
        },
        Deck {
            file: "abaqus_fric_coef.inp",
            title: "the friction coefficient alone through FRIC_COEF (Abaqus/Standard)",
            routine: Routine::FricCoef,
            interaction: "SI_COEF",
            depvar: None,
            props: Some((&COULOMB, decay.clone())),
            notes: &[
                "Abaqus keeps its own Coulomb model and asks FRIC_COEF for mu and its derivatives;",
                "law 1's mu entries apply (here the exponential decay). FRIC_COEF has no DEPVAR.",
            ],
        },
        Deck {
            file: "abaqus_vfric.inp",
            title: "Coulomb friction for kinematic contact through VFRIC (Abaqus/Explicit)",
            routine: Routine::Vfric,
            interaction: "SI_EXPLICIT",
            depvar: None,
            props: Some((&COULOMB, CoulombBuilder::new().mu(0.3).build_first(7))),
            notes: &[
                "Law 1 without the extended entries (docs/vfric.md): mu = 0.3, no force cap.",
                "VFRIC writes no state variables, so no DEPVAR. A single-precision Explicit run",
                "needs the explicit-single build of the library.",
            ],
        },
        Deck {
            file: "abaqus_gapcon.inp",
            title: "gap conductance through GAPCON (Abaqus/Standard)",
            routine: Routine::Gapcon,
            interaction: "SI_THERMAL",
            depvar: None,
            props: None,
            notes: &[
                "GAPCON has no PROPS: the law of the interaction comes from the TOML file named by",
                "INTERFACIAL_CONFIG, here examples/decks/interfacial.toml (docs/config.md).",
                "Used in a coupled temperature-displacement or heat transfer step.",
            ],
        },
        Deck {
            file: "calculix_gapcon.inp",
            title: "gap conductance through CalculiX's gapcon",
            routine: Routine::GapconCalculix,
            interaction: "SI_THERMAL",
            depvar: None,
            props: None,
            notes: &[
                "CalculiX calls gapcon for penalty contact only, with the interaction's name as",
                "CINAME; link libinterfacial_calculix (docs/install.md, CalculiX) and set",
                "INTERFACIAL_CONFIG to a file such as examples/decks/interfacial.toml.",
                "Keep the interaction's *SURFACE BEHAVIOR lines as they are.",
            ],
        },
    ]
}

/// A value as a data line shows it: integers with a trailing point, others in Rust's shortest
/// round-trip form (which Fortran list input reads back exactly).
fn number(v: f64) -> String {
    if v == v.trunc() && v.abs() < 1e15 {
        format!("{v:.0}.")
    } else {
        let plain = format!("{v}");
        if plain.len() <= 8 {
            plain
        } else {
            format!("{v:e}")
        }
    }
}

/// The data lines of `values`, eight a line.
fn data_lines(values: &[f64]) -> String {
    let mut s = String::new();
    for chunk in values.chunks(8) {
        let line: Vec<String> = chunk.iter().map(|&v| number(v)).collect();
        s.push_str(&line.join(", "));
        s.push('\n');
    }
    s
}

/// `text` in ASCII, for a deck: the solvers read their input as ASCII. The symbols of the
/// layouts' descriptions are spelled out; a character without a spelling here fails the test,
/// so a new symbol gets one.
fn ascii(text: &str) -> String {
    let mut s = String::new();
    for c in text.chars() {
        let spelled = match c {
            c if c.is_ascii() => {
                s.push(c);
                continue;
            }
            'μ' => "mu",
            'τ' => "tau",
            'γ' => "gamma",
            'θ' => "theta",
            'α' => "alpha",
            'β' => "beta",
            'η' => "eta",
            'ω' => "omega",
            'κ' => "kappa",
            '₀' => "0",
            '₁' => "1",
            '₂' => "2",
            '½' => "1/2",
            '²' => "^2",
            '→' => "->",
            '←' => "<-",
            '≤' => "<=",
            '≥' => ">=",
            '×' => "x",
            '·' => "*",
            '−' => "-",
            '—' => "-",
            '–' => "-",
            '̄' => "_bar",
            '̇' => "_dot",
            other => panic!("no ASCII spelling for `{other}` in `{text}`"),
        };
        s.push_str(spelled);
    }
    s
}

/// One comment line per entry: `PROPS(i) = value  key: meaning [symbol, unit]`.
fn props_comments(layout: &'static Layout, props: &[f64]) -> String {
    let mut s = String::new();
    for (i, &v) in props.iter().enumerate() {
        let e = layout.entry_in(props, i + 1);
        let mut extra = Vec::new();
        if !e.symbol.is_empty() {
            extra.push(e.symbol);
        }
        if !e.unit.is_empty() {
            extra.push(e.unit);
        }
        let extra = if extra.is_empty() {
            String::new()
        } else {
            format!(" [{}]", extra.join(", "))
        };
        s.push_str(&ascii(&format!(
            "** PROPS({}) = {}  {}: {}{}\n",
            e.index,
            number(v),
            e.key,
            e.meaning,
            extra
        )));
    }
    s
}

fn render(deck: &Deck) -> String {
    let mut s = format!(
        "** {} -- {}.\n\
         ** Generated from the PROPS layouts (src/props) by\n\
         **   INTERFACIAL_BLESS=1 cargo test --test decks\n\
         ** do not edit. How to use it: docs/input-decks.md.\n",
        deck.file, deck.title
    );
    for note in deck.notes {
        s.push_str(&format!("** {note}\n"));
    }
    s.push_str(&format!(
        "** The interaction's name reaches the library as CINAME ({}).\n**\n",
        deck.interaction
    ));
    let nprops = deck.props.as_ref().map_or(0, |(_, p)| p.len());
    let depvar = deck
        .depvar
        .map(|n| format!(", DEPVAR={n}"))
        .unwrap_or_default();
    match deck.routine {
        Routine::Fric | Routine::Vfric => {
            s.push_str(&format!(
                "*SURFACE INTERACTION, NAME={}\n",
                deck.interaction
            ));
            s.push_str(&format!("*FRICTION, USER{depvar}, PROPERTIES={nprops}\n"));
        }
        Routine::FricCoef => {
            s.push_str(&format!(
                "*SURFACE INTERACTION, NAME={}\n",
                deck.interaction
            ));
            s.push_str(&format!(
                "*FRICTION, USER=COEFFICIENT, PROPERTIES={nprops}\n"
            ));
        }
        Routine::Uinter => {
            s.push_str(&format!(
                "*SURFACE INTERACTION, NAME={}, USER{depvar}, PROPERTIES={nprops}, UNSYMM\n",
                deck.interaction
            ));
            s.push_str(
                "** First data line: the out-of-plane thickness in 2-D (or the area of a\n\
                 ** node-based surface); blank in 3-D, as here. Then the PROPS.\n\n",
            );
        }
        Routine::Gapcon | Routine::GapconCalculix => {
            s.push_str(&format!(
                "*SURFACE INTERACTION, NAME={}\n",
                deck.interaction
            ));
            s.push_str("*GAP CONDUCTANCE, USER\n");
        }
    }
    if let Some((layout, props)) = &deck.props {
        s.push_str(&props_comments(layout, props));
        s.push_str(&data_lines(props));
    }
    s
}

/// A keyword line read back: the keyword (upper case) and its parameters (upper-case names,
/// values as written, `None` for a bare parameter), with the data lines that follow it.
#[derive(Debug)]
struct Keyword {
    name: String,
    params: Vec<(String, Option<String>)>,
    data: Vec<String>,
}

impl Keyword {
    fn param(&self, name: &str) -> Option<Option<&str>> {
        self.params
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_deref())
    }

    fn count(&self, name: &str) -> Result<usize, String> {
        match self.param(name) {
            Some(Some(v)) => v
                .parse()
                .map_err(|_| format!("*{}: {name}={v} is not a count", self.name)),
            _ => Err(format!("*{}: no {name}=", self.name)),
        }
    }
}

/// The keyword lines of a deck with their data lines; `**` comments skipped.
fn parse_deck(text: &str) -> Vec<Keyword> {
    let mut out: Vec<Keyword> = Vec::new();
    for line in text.lines() {
        if line.starts_with("**") {
            continue;
        }
        if let Some(rest) = line.strip_prefix('*') {
            let mut parts = rest.split(',').map(str::trim);
            let name = parts.next().unwrap_or("").to_ascii_uppercase();
            let params = parts
                .filter(|p| !p.is_empty())
                .map(|p| match p.split_once('=') {
                    Some((k, v)) => (k.trim().to_ascii_uppercase(), Some(v.trim().to_string())),
                    None => (p.to_ascii_uppercase(), None),
                })
                .collect();
            out.push(Keyword {
                name,
                params,
                data: Vec::new(),
            });
        } else if let Some(k) = out.last_mut() {
            k.data.push(line.to_string());
        }
    }
    out
}

/// The values of data lines, comma-separated.
fn values(lines: &[String]) -> Result<Vec<f64>, String> {
    let mut v = Vec::new();
    for line in lines {
        for field in line.split(',') {
            let field = field.trim();
            if field.is_empty() {
                continue;
            }
            v.push(
                field
                    .parse::<f64>()
                    .map_err(|_| format!("data value `{field}` is not a number"))?,
            );
        }
    }
    Ok(v)
}

/// The library's verdict on a fragment's text, read as the solver reads it.
fn validate(routine: Routine, text: &str, config: &Config) -> Result<(), String> {
    let keywords = parse_deck(text);
    let find = |name: &str| {
        keywords
            .iter()
            .find(|k| k.name == name)
            .ok_or_else(|| format!("no *{name} line"))
    };
    let interaction = find("SURFACE INTERACTION")?;
    let name = match interaction.param("NAME") {
        Some(Some(n)) => n.to_string(),
        _ => return Err("*SURFACE INTERACTION without NAME=".into()),
    };
    match routine {
        Routine::Gapcon | Routine::GapconCalculix => {
            let gap = find("GAP CONDUCTANCE")?;
            if gap.param("USER") != Some(None) || !gap.data.is_empty() {
                return Err("*GAP CONDUCTANCE must be USER with no data lines".into());
            }
            let Some(law) = config.gap_law(name.as_bytes()) else {
                return Err(format!("{CONFIG} has no conductance law for {name}"));
            };
            // A closed point at 1 MPa: a usable conductance.
            let k = law
                .evaluate(0.0, 1e6, 300.0, 290.0)
                .map_err(|e| e.to_string())?
                .k;
            if !(k.is_finite() && k > 0.0) {
                return Err(format!("{name}: conductance {k} at a closed point"));
            }
            Ok(())
        }
        Routine::Fric | Routine::FricCoef | Routine::Vfric => {
            let friction = find("FRICTION")?;
            let user = friction.param("USER");
            let expected = if routine == Routine::FricCoef {
                Some(Some("COEFFICIENT"))
            } else {
                Some(None)
            };
            if user != expected {
                return Err(format!("*FRICTION USER is {user:?}, expected {expected:?}"));
            }
            let props = values(&friction.data)?;
            let nprops = friction.count("PROPERTIES")?;
            if props.len() != nprops {
                return Err(format!(
                    "PROPERTIES={nprops} but {} data values",
                    props.len()
                ));
            }
            let law = friction_law_checked(&props).map_err(|e| e.to_string())?;
            // The same PROPS as a pre-processor asks about them, through the C API.
            tool_check(&props, &name)?;
            match routine {
                Routine::Fric => {
                    let depvar = friction.count("DEPVAR")?;
                    fric_increment(&name, &props, depvar)
                }
                Routine::Vfric if !matches!(law, FrictionLaw::Coulomb(_)) => {
                    Err("VFRIC takes the plain law-1 entries only (docs/vfric.md)".into())
                }
                Routine::Vfric => vfric_block(&props),
                _ => fric_coef_block(&name, &props),
            }
        }
        Routine::Uinter => {
            if interaction.param("USER") != Some(None) {
                return Err("*SURFACE INTERACTION without USER".into());
            }
            // The first data line is the thickness line (blank in 3-D), then the PROPS.
            let Some((thickness, rest)) = interaction.data.split_first() else {
                return Err("no data lines".into());
            };
            if !thickness.trim().is_empty() {
                return Err("the first data line of a 3-D UINTER deck must be blank".into());
            }
            let props = values(rest)?;
            let nprops = interaction.count("PROPERTIES")?;
            if props.len() != nprops {
                return Err(format!(
                    "PROPERTIES={nprops} but {} data values",
                    props.len()
                ));
            }
            match friction_law_checked(&props).map_err(|e| e.to_string())? {
                FrictionLaw::Adhesive(a) => {
                    a.interface().map_err(|e| e.to_string())?;
                }
                _ => return Err("UINTER runs law 2 only (docs/uinter.md)".into()),
            }
            uinter_increment(&name, &props, interaction.count("DEPVAR")?)
        }
    }
}

/// Runs `entry` (a call into the library) with the thread's last error cleared; `Err` with the
/// message the call left, if it left one.
fn no_error<T>(entry: impl FnOnce() -> T) -> Result<T, String> {
    ifl_clear_error();
    let answer = entry();
    let error = FricCall::last_error();
    if error.is_empty() {
        Ok(answer)
    } else {
        Err(error)
    }
}

/// The interaction's name, NSTATV = the deck's `DEPVAR=` and that many state variables (and
/// four more past them, which the routine must not write), as the solver passes them.
fn as_declared(name: &str, depvar: usize) -> Result<(String, i32, Vec<f64>), String> {
    let nstatv = i32::try_from(depvar).map_err(|e| e.to_string())?;
    Ok((name.to_string(), nstatv, vec![0.0; depvar + 4]))
}

/// One increment of a closed, sliding point through `fric_` as the solver would call it.
fn fric_increment(name: &str, props: &[f64], depvar: usize) -> Result<(), String> {
    let mut call = FricCall::new(2, props);
    (call.ciname, call.nstatv, call.statev) = as_declared(name, depvar)?;
    call.set_guards();
    call.press = 100.0;
    call.dpress = 100.0;
    call.dgam = [1e-2, 5e-3, 0.0];
    no_error(|| call.call())?;
    if call.lm != 0 || !call.tau[..2].iter().all(|t| t.is_finite()) || !call.guards_intact() {
        return Err(format!(
            "FRIC answered LM = {}, TAU = {:?}",
            call.lm,
            &call.tau[..2]
        ));
    }
    Ok(())
}

/// One point through `fric_coef_`: with the decay law (`PROPS(8) = 1`) μ must be its closed
/// form μ_k + (μ_s − μ_k)·exp(−d_c·v) at the slip rate v, from the deck's own values; with
/// constant μ, `PROPS(2)`.
fn fric_coef_block(name: &str, props: &[f64]) -> Result<(), String> {
    let entry = |i: usize| props.get(i - 1).copied().unwrap_or(0.0);
    let rate = 0.25;
    let mut coef = [0.0; 2];
    let mut deriv = [0.0; 40];
    let mut slip = [0.0; 6];
    slip[0] = rate;
    slip[1] = rate;
    no_error(|| {
        fric_coef_common::fric_coef_call(
            &mut coef,
            &mut deriv,
            props,
            &slip,
            &[100.0],
            &[20.0],
            name.as_bytes(),
        );
    })?;
    let expected = if entry(8) == 1.0 {
        entry(9) + (entry(2) - entry(9)) * (-entry(10) * rate).exp()
    } else {
        entry(2)
    };
    if (coef[0] - expected).abs() > 1e-14 * expected.abs() {
        return Err(format!(
            "FRIC_COEF answered mu = {}, expected {expected}",
            coef[0]
        ));
    }
    Ok(())
}

/// One contact point through `vfric_`: F = min(μ·F_N, F_stick) against the slip
/// (docs/vfric.md), here with F_stick large so that it slips at μ·F_N.
fn vfric_block(props: &[f64]) -> Result<(), String> {
    use vfric_common::{Block, call};
    type Real = interfacial::abi::vfric::IflReal;
    let real: Vec<Real> = props.iter().map(|&v| v as Real).collect();
    let (f_normal, f_stick): (Real, Real) = (100.0, 1000.0);
    let expected = -(real[1] * f_normal).min(f_stick);
    let block = Block {
        nfricdir: 2,
        props: real,
        f_normal: vec![f_normal],
        f_stick: vec![f_stick],
        area: vec![1.0],
        jconslvid: vec![1],
    };
    let ftan = no_error(|| call(&block))?;
    // Relative 1e-6: single precision with the explicit-single build.
    if (ftan[0] - expected).abs() > 1e-6 * expected.abs() {
        return Err(format!("VFRIC answered {}, expected {expected}", ftan[0]));
    }
    Ok(())
}

/// One increment of a point in contact through `uinter_` as the solver would call it.
fn uinter_increment(name: &str, props: &[f64], depvar: usize) -> Result<(), String> {
    let mut call = UinterCall::new(3, props);
    (call.ciname, call.nstatv, call.statev) = as_declared(name, depvar)?;
    call.set_guards();
    call.rdisp = [1e-4, 1e-3, 0.0];
    call.drdisp = [1e-4, 1e-3, 0.0];
    no_error(|| call.call())?;
    // Closed: the normal stress is the penalty K_n·h (docs/uinter.md).
    let h = call.rdisp[0];
    let kn = props.get(9).copied().unwrap_or(0.0);
    let p = call.stress[0];
    if (p - kn * h).abs() > 1e-12 * (kn * h).abs() || !call.guards_intact() {
        return Err(format!(
            "UINTER answered STRESS = {:?}, expected p = K_n h = {}",
            &call.stress[..3],
            kn * h
        ));
    }
    Ok(())
}

/// `ifl_props_check` (docs/c-api.md) on `props` for the interaction `name`: what a
/// pre-processor asks before a run; `Err` with the library's message when it would refuse them.
fn tool_check(props: &[f64], name: &str) -> Result<(), String> {
    let name = CString::new(name.trim_end()).map_err(|e| e.to_string())?;
    let mut message = [0 as c_char; 512];
    let mut len = 0usize;
    // SAFETY: `props` holds `props.len()` doubles, `name` is NUL-terminated, `message` has the
    // capacity given and `len` is writable.
    let status = unsafe {
        ifl_props_check(
            props.as_ptr(),
            c_int::try_from(props.len()).map_err(|e| e.to_string())?,
            name.as_ptr(),
            message.as_mut_ptr(),
            message.len(),
            &mut len,
        )
    };
    if status == IflStatus::Ok {
        Ok(())
    } else {
        // SAFETY: the library NUL-terminates the message within the capacity.
        let text = unsafe { CStr::from_ptr(message.as_ptr()) };
        Err(format!("ifl_props_check: {}", text.to_string_lossy()))
    }
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn example_config() -> Config {
    let path = root().join(DECKS).join(CONFIG);
    let text = std::fs::read_to_string(&path).expect("read examples/decks/interfacial.toml");
    Config::parse(&path.to_string_lossy(), &text).expect("examples/decks/interfacial.toml")
}

#[test]
fn deck_fragments_are_up_to_date() {
    let dir = root().join(DECKS);
    let bless = std::env::var_os("INTERFACIAL_BLESS").is_some();
    let mut stale = Vec::new();
    for deck in decks() {
        let rendered = render(&deck);
        assert!(rendered.is_ascii(), "{} is not ASCII", deck.file);
        let path = dir.join(deck.file);
        if bless {
            std::fs::write(&path, &rendered).expect("write a deck fragment");
            continue;
        }
        let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
        if on_disk != rendered {
            stale.push(deck.file);
        }
    }
    assert!(
        stale.is_empty(),
        "{stale:?} differ from the PROPS layouts; regenerate with:\n    \
         INTERFACIAL_BLESS=1 cargo test --test decks"
    );
    // Nothing else in the folder: a fragment removed here must go from the folder too.
    let mut expected: Vec<String> = decks().iter().map(|d| d.file.to_string()).collect();
    expected.push(CONFIG.to_string());
    expected.sort();
    let mut found: Vec<String> = std::fs::read_dir(&dir)
        .expect("read examples/decks")
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    found.sort();
    assert_eq!(found, expected, "examples/decks holds other files");
}

#[test]
fn every_fragment_is_accepted_by_the_library() {
    let config = example_config();
    for deck in decks() {
        // Under INTERFACIAL_BLESS the files are being rewritten by the test above: check what
        // it writes.
        let text = if std::env::var_os("INTERFACIAL_BLESS").is_some() {
            render(&deck)
        } else {
            let path = root().join(DECKS).join(deck.file);
            std::fs::read_to_string(&path).expect("read a deck fragment")
        };
        if let Err(e) = validate(deck.routine, &text, &config) {
            panic!("{}: {e}", deck.file);
        }
        // The data lines read back are the layout's values, bit for bit.
        if let Some((_, props)) = &deck.props {
            let keywords = parse_deck(&text);
            let data: Vec<String> = keywords
                .iter()
                .flat_map(|k| k.data.iter().cloned())
                .collect();
            let back = values(&data).expect("numbers");
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&back), bits(props), "{}", deck.file);
        }
    }
}

/// The checks can fail: a fragment with a wrong count, a bad value, too few state variables or
/// an interaction without a law is refused, each with the library's reason.
#[test]
fn a_bad_fragment_is_refused() {
    // The C API's check refuses what the checked parser refuses, naming the entry.
    let refused = tool_check(&[1.0, -0.3], "BAD_MU").unwrap_err();
    assert!(refused.contains("PROPS(2)"), "{refused}");
    assert_eq!(tool_check(&[1.0, 0.3], "GOOD_MU"), Ok(()));
    let config = example_config();
    let all = decks();
    let by_file = |f: &str| all.iter().find(|d| d.file == f).expect("a fragment");
    // Each fragment with its routine and interaction name.
    #[rustfmt::skip]
    let [coulomb, rate_state, uinter] = [
        (Routine::Fric, "SI_COULOMB", "abaqus_fric_coulomb.inp"),
        (Routine::Fric, "SI_RATE_STATE", "abaqus_fric_rate_state.inp"),
        (Routine::Uinter, "SI_ADHESIVE", "abaqus_uinter_adhesive.inp"),
    ]
    .map(|(routine, name, file)| (routine, name, render(by_file(file))));
    let gapcon = render(by_file("abaqus_gapcon.inp"));
    // Each case under its own interaction name: a refused configuration is remembered per
    // interaction, and the good fragments run in the same process. (fragment, its new name, a
    // text edited from → to, the reason the refusal must give.)
    #[rustfmt::skip]
    let edits = [
        (&coulomb, "BAD_COUNT", "PROPERTIES=7", "PROPERTIES=8", "PROPERTIES=8 but 7"),
        (&coulomb, "BAD_MU", "1., 0.3,", "1., -0.3,", "PROPS(2)"),
        (&coulomb, "BAD_DEPVAR", "DEPVAR=3", "DEPVAR=2", "NSTATV"),
        (&rate_state, "BAD_RATE_STATE_DEPVAR", "DEPVAR=4", "DEPVAR=3", "NSTATV = 3"),
        (&uinter, "BAD_KN", ", 1000000.\n", ", 0.\n", "K_n > 0"),
    ];
    let mut cases: Vec<(Routine, String, &str)> = edits
        .iter()
        .map(|((routine, name, text), bad_name, from, to, reason)| {
            let edited = text.replace(name, bad_name).replace(from, to);
            (*routine, edited, *reason)
        })
        .collect();
    cases.push((
        Routine::Gapcon,
        gapcon.replace("SI_THERMAL", "NO_SUCH_INTERACTION"),
        "no conductance law",
    ));
    for (routine, text, reason) in cases {
        match validate(routine, &text, &config) {
            Ok(()) => panic!("accepted:\n{text}"),
            Err(e) => assert!(e.contains(reason), "refused for another reason: {e}"),
        }
    }
}
