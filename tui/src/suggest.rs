//! "Did you mean …?" for a mistyped subcommand, flag, parameter path, preset or model name: the
//! closest known name by edit distance (optimal string alignment: a swap of two neighbouring
//! letters, `esp` for `eps`, counts one), offered only when it is close (issue 37).

/// The optimal-string-alignment distance between `a` and `b` (insertions, deletions,
/// substitutions and swaps of neighbours, each 1), over characters.
pub fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let (n, m) = (a.len(), b.len());
    let mut d = vec![vec![0_usize; m + 1]; n + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=n {
        for j in 1..=m {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[n][m]
}

/// The known name closest to `given`, if it is close: at most 2 edits, and fewer than half the
/// given name's characters (so `x` is never "corrected" to `y`: names of one or two characters
/// get no suggestion). Ties go to the first candidate.
pub fn closest<'a>(given: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let limit = 2.min(given.chars().count().saturating_sub(1) / 2);
    candidates
        .into_iter()
        .map(|c| (distance(given, c), c))
        .filter(|(d, _)| *d >= 1 && *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// ` (did you mean `eps`?)` when a close name exists, else empty.
pub fn hint<'a>(given: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    closest(given, candidates).map_or(String::new(), |c| format!(" (did you mean `{c}`?)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 37 item 13: distances counted by hand.
    #[test]
    fn issue_37_edit_distances() {
        assert_eq!(distance("esp", "eps"), 1, "a swap of neighbours");
        assert_eq!(distance("--gg", "--g"), 1);
        assert_eq!(distance("bulk.dampin.time", "bulk.damping.time"), 1);
        assert_eq!(distance("kitten", "sitting"), 3);
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(distance("same", "same"), 0);
    }

    #[test]
    fn issue_37_only_close_names_are_offered() {
        let subs = ["eps", "curve", "map", "ring", "tidal"];
        assert_eq!(closest("esp", subs), Some("eps"));
        assert_eq!(closest("rign", subs), Some("ring"));
        assert_eq!(closest("xyz", subs), None);
        // One letter is never "corrected".
        assert_eq!(closest("q", ["a", "b"]), None);
        assert_eq!(hint("tidl", subs), " (did you mean `tidal`?)");
        assert_eq!(hint("banana", subs), "");
    }
}
