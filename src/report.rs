//! Error reporting shared by every entry point: one line per distinct cause to stderr (or the
//! file named by `INTERFACIAL_LOG`, or the host's handler set by `ifl_set_message_handler`), the
//! last message of each thread kept for `ifl_last_error`, and `INTERFACIAL_STRICT` (`1`, `yes`,
//! `true` or `on`, any case) to abort on the first error.
//!
//! The last error is sticky, like `errno`: [`report`] replaces it, [`clear_last_error`]
//! (`ifl_clear_error`) empties it, and nothing else touches it — a successful call leaves it as
//! it was (docs/install.md, "Errors"; `tests/last_error.rs` holds every entry point to that).
//!
//! The only global mutable state of the library lives here: the set of causes already printed
//! (a mutex, touched only on the error path, at most [`MAX_CAUSES`] entries) and the
//! environment read once.

use std::cell::{Cell, RefCell};
use std::collections::HashSet;
use std::ffi::CString;
use std::io::Write;
use std::sync::{Mutex, OnceLock, PoisonError};

/// Where a message comes from: the routine and what the host told us about the point.
#[derive(Clone, Debug, Default)]
pub(crate) struct Site {
    /// Abaqus routine name, upper case (`FRIC`).
    pub routine: &'static str,
    /// Interaction name, blank-trimmed.
    pub interaction: String,
    /// "element 12, node 7, point 1", as far as the routine knows it.
    pub place: String,
}

struct Settings {
    log_file: Option<String>,
    strict: bool,
}

fn settings() -> &'static Settings {
    static SETTINGS: OnceLock<Settings> = OnceLock::new();
    SETTINGS.get_or_init(|| {
        let strict = std::env::var("INTERFACIAL_STRICT").unwrap_or_default();
        let settings = Settings {
            log_file: std::env::var("INTERFACIAL_LOG")
                .ok()
                .filter(|s| !s.is_empty()),
            strict: parse_strict(&strict).unwrap_or(false),
        };
        if parse_strict(&strict).is_none() {
            emit(
                &settings,
                &format!(
                    "interfacial: INTERFACIAL_STRICT={strict:?} is not understood (1, yes, true, \
                     on or 0, no, false, off); not aborting on errors"
                ),
            );
        }
        settings
    })
}

/// `INTERFACIAL_STRICT`'s value: `Some(true)` for 1, yes, true, on; `Some(false)` for unset or
/// empty, 0, no, false, off (any case, blanks trimmed); `None` for anything else.
pub(crate) fn parse_strict(value: &str) -> Option<bool> {
    match value.trim().to_ascii_lowercase().as_str() {
        "1" | "yes" | "true" | "on" => Some(true),
        "" | "0" | "no" | "false" | "off" => Some(false),
        _ => None,
    }
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Formats, records and (once per cause) prints a message. Returns the full message. With
/// `per_interaction` false the cause is printed once for the whole run (a bad configuration
/// file), not once per interaction that meets it.
pub(crate) fn report(site: &Site, cause: &str, per_interaction: bool) -> String {
    let message = format!(
        "interfacial: {}: interaction '{}' ({}): {}",
        site.routine, site.interaction, site.place, cause
    );
    set_last_error(&message);
    // Once per (routine, interaction, cause): the same bad input at a million points is one
    // line, not a million.
    static SEEN: OnceLock<Mutex<HashSet<String>>> = OnceLock::new();
    let scope = if per_interaction {
        site.interaction.as_str()
    } else {
        ""
    };
    let key = format!("{}\u{1f}{}\u{1f}{}", site.routine, scope, cause);
    let verdict = SEEN
        .get_or_init(|| Mutex::new(HashSet::new()))
        .lock()
        .map(|mut seen| {
            if seen.len() < MAX_CAUSES {
                if seen.insert(key) {
                    Verdict::Print
                } else {
                    Verdict::Repeat
                }
            } else if seen.contains(&key) || !seen.insert(SUPPRESSED_KEY.to_owned()) {
                // Full: the set no longer grows (one more entry, the suppression marker).
                Verdict::Repeat
            } else {
                Verdict::Suppress
            }
        })
        // A poisoned set still reports: better a repeated line than a lost one.
        .unwrap_or(Verdict::Print);
    let s = settings();
    match verdict {
        Verdict::Print => emit(s, &message),
        Verdict::Suppress => emit(
            s,
            &format!(
                "interfacial: {MAX_CAUSES} distinct error causes reported; further messages \
                 suppressed (ifl_last_error still gives each call's message)"
            ),
        ),
        Verdict::Repeat => {}
    }
    if s.strict {
        emit(
            s,
            "interfacial: INTERFACIAL_STRICT is set, aborting on the first error",
        );
        std::process::abort();
    }
    message
}

/// Distinct causes printed per process; then one "further messages suppressed" line and no
/// more, so that a run meeting ever new causes (each with its own numbers) neither floods the
/// log nor grows the set of causes seen without bound.
pub(crate) const MAX_CAUSES: usize = 10_000;

/// Set entry marking that the suppression line has been printed (no real key is empty).
const SUPPRESSED_KEY: &str = "";

enum Verdict {
    Print,
    Repeat,
    Suppress,
}

/// A host's receiver of every message (`ifl_set_message_handler`, src/abi/message_hook.rs),
/// given each message whole, without its newline.
pub(crate) type Sink = Box<dyn Fn(&str) + Send + Sync>;

/// The host's sink, when one is set; its lock also makes the calls one at a time.
static SINK: Mutex<Option<Sink>> = Mutex::new(None);

thread_local! {
    /// True while this thread runs the sink (a message it raises goes to stderr or the file).
    static IN_SINK: Cell<bool> = const { Cell::new(false) };
    /// A sink set from inside the sink on this thread, put in place once it returns.
    static SINK_REPLACEMENT: RefCell<Option<Option<Sink>>> = const { RefCell::new(None) };
}

/// Sends every later message to `sink` instead of stderr or the file (`None`: back to them).
/// When it returns, the previous sink is not running on any thread and is never called again;
/// called from inside the sink, the change takes effect as the sink returns.
pub(crate) fn set_sink(sink: Option<Sink>) {
    if IN_SINK.get() {
        SINK_REPLACEMENT.with(|r| *r.borrow_mut() = Some(sink));
        return;
    }
    let old = std::mem::replace(
        &mut *SINK.lock().unwrap_or_else(PoisonError::into_inner),
        sink,
    );
    drop(old);
}

fn emit(s: &Settings, line: &str) {
    if IN_SINK.get() {
        // The sink called into the library, which reported: not back into the sink.
        write_out(s, line);
        return;
    }
    let mut sink = SINK.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(f) = sink.as_ref() {
        IN_SINK.set(true);
        f(line);
        IN_SINK.set(false);
        if let Some(replacement) = SINK_REPLACEMENT.with(|r| r.borrow_mut().take()) {
            *sink = replacement;
        }
        return;
    }
    write_out(s, line);
}

/// Writes a message to the `INTERFACIAL_LOG` file or stderr.
fn write_out(s: &Settings, line: &str) {
    // One write of the whole line, under a lock: messages from several threads never interleave.
    static EMIT: Mutex<()> = Mutex::new(());
    let _serial = EMIT.lock();
    let text = format!("{line}\n");
    if let Some(path) = &s.log_file {
        let written = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)
            .and_then(|mut f| f.write_all(text.as_bytes()));
        if written.is_ok() {
            return;
        }
        let _ = std::io::stderr().write_all(
            format!("interfacial: cannot write INTERFACIAL_LOG={path}; reporting to stderr\n")
                .as_bytes(),
        );
    }
    let _ = std::io::stderr().write_all(text.as_bytes());
}

pub(crate) fn set_last_error(message: &str) {
    // Interior NULs cannot come from our own messages, but a host's names could hold one.
    let c = CString::new(message.replace('\0', " ")).unwrap_or_default();
    LAST_ERROR.with(|e| *e.borrow_mut() = c);
}

pub(crate) fn clear_last_error() {
    LAST_ERROR.with(|e| *e.borrow_mut() = CString::default());
}

/// Runs `f` on the calling thread's last message (empty when there is none).
pub(crate) fn with_last_error<R>(f: impl FnOnce(&CString) -> R) -> R {
    LAST_ERROR.with(|e| f(&e.borrow()))
}
