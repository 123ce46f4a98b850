//! The committed tables' text form as lines: `#` header lines (the command, the commit, the
//! settings), then records of comma-separated fields. Shared by the master and the restitution
//! tables' readers, with nothing but `std`: the build script includes this file too.

/// The `#` lines of `text` (the `#` and the blanks after it taken off), and its other lines,
/// each with its 1-based number (for the reader's errors).
pub fn split(text: &str) -> (Vec<String>, Vec<(usize, &str)>) {
    let mut header = Vec::new();
    let mut records = Vec::new();
    for (i, line) in text.lines().enumerate() {
        match line.strip_prefix('#') {
            Some(h) => header.push(h.trim_start().to_string()),
            None => records.push((i + 1, line)),
        }
    }
    (header, records)
}

#[cfg(test)]
mod tests {
    /// Header lines lose their `#` and leading blanks, wherever they stand; the other lines keep
    /// their numbers in the text.
    #[test]
    fn header_and_numbered_records() {
        let (header, records) = super::split("# a\nk,1\n#  b\n\nrow,2");
        assert_eq!(header, ["a", "b"]);
        assert_eq!(records, [(2, "k,1"), (4, ""), (5, "row,2")]);
    }
}
