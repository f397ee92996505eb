//! CSV output of the main job (RFC 4180): every field that holds a comma, a double quote or a
//! line break is quoted, quotes doubled, so that a CSV reader finds as many fields in every row
//! as in the header (`tests/scenes_job.rs` parses every file the job writes).

/// One field, quoted when it must be.
pub fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}
