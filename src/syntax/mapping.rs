//! Offset maps: where each piece of generated text came from.
//!
//! In: pieces of text appended to an output, each with the source span it stands for.
//! Out: source spans for output ranges, so nodes parsed from generated text (a text macro's
//! expansion, a directive parsed on its own) point into the original file. Holds: pieces are
//! recorded in increasing output order.

use crate::diag::Span;

/// Maps byte offsets of generated text back to spans of source files.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct OffsetMap {
    /// `(output offset where the piece starts, the source span it stands for)`.
    pieces: Vec<(usize, Span)>,
}

impl OffsetMap {
    /// A map with no pieces yet.
    pub fn new() -> OffsetMap {
        OffsetMap::default()
    }

    /// A map for text copied unchanged from `source` (a directive parsed on its own).
    pub fn copied(source: Span) -> OffsetMap {
        OffsetMap {
            pieces: vec![(0, source)],
        }
    }

    /// Records that the output from offset `output` on stands for `source`, until the next
    /// piece.
    pub fn record(&mut self, output: usize, source: Span) {
        self.pieces.push((output, source));
    }

    /// The piece covering output offset `offset`.
    fn piece(&self, offset: usize) -> Option<(usize, Span)> {
        let index = self.pieces.partition_point(|(start, _)| *start <= offset);
        self.pieces.get(index.checked_sub(1)?).copied()
    }

    /// The source span of output bytes `start..end`: from where the piece holding `start`
    /// points to where the piece holding the last byte points, or the first piece alone when
    /// the two lie in different files or out of order (a loop emitted them).
    pub fn span(&self, start: usize, end: usize) -> Span {
        let Some((first_start, first)) = self.piece(start) else {
            return Span::default();
        };
        let inside = |piece_start: usize, piece: Span, offset: usize| {
            (piece.start as usize + (offset - piece_start)).min(piece.end as usize)
        };
        let source_start = inside(first_start, first, start);
        let (last_start, last) = self
            .piece(end.saturating_sub(1).max(start))
            .unwrap_or((first_start, first));
        let source_end = inside(last_start, last, end);
        if last.file != first.file || source_end < source_start {
            return Span::new(first.file, source_start, first.end as usize);
        }
        Span::new(first.file, source_start, source_end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copied_text_shifts_offsets() {
        let map = OffsetMap::copied(Span::new(3, 100, 120));
        assert_eq!(map.span(2, 5), Span::new(3, 102, 105));
    }

    #[test]
    fn pieces_map_to_their_sources() {
        let mut map = OffsetMap::new();
        map.record(0, Span::new(1, 50, 55)); // "mesh2" then a space
        map.record(6, Span::new(1, 10, 11)); // a name emitted as a longer hidden name
        assert_eq!(map.span(0, 5), Span::new(1, 50, 55));
        assert_eq!(map.span(6, 14), Span::new(1, 10, 11));
        // Out of order: the first piece alone.
        assert_eq!(map.span(0, 14), Span::new(1, 50, 55));
    }
}
