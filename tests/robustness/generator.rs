//! The mutations: each a pure function of the input and a random stream.

use ugo::random::Rng;

/// Numbers that break careless readers: zero and signs, the ends of the double range,
/// subnormals, non-numbers, integers past 32 and 64 bits, and text where a number belongs.
pub const HOSTILE_NUMBERS: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e308",
    "-1e308",
    "1e39",
    "1e-320",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "4294967297",
    "9223372036854775807",
    "18446744073709551616",
    "1e150",
    "1e-300",
    "0.0000001",
    "3.5",
    "abc",
    "",
    "1,5",
    "0x10",
    "1e",
    "--1",
];

pub struct Mutator {
    rng: Rng,
}

impl Mutator {
    pub fn new(seed: u64, index: u64) -> Mutator {
        Mutator { rng: Rng::stream(seed, index) }
    }

    fn below(&mut self, n: usize) -> usize {
        (self.rng.next_u64() % n.max(1) as u64) as usize
    }

    /// One mutation of `input`, and its name for the report.
    pub fn mutate(&mut self, input: &[u8]) -> (Vec<u8>, String) {
        let text = String::from_utf8_lossy(input).into_owned();
        let lines: Vec<&str> = text.lines().collect();
        let kind = self.below(9);
        match kind {
            0 => {
                let at = self.below(input.len() + 1);
                (input[..at].to_vec(), format!("truncated at byte {at}"))
            }
            1 if !lines.is_empty() => {
                let at = self.below(lines.len());
                (lines[..at].join("\n").into_bytes(), format!("truncated before line {}", at + 1))
            }
            2 if !lines.is_empty() => {
                let at = self.below(lines.len());
                let mut out = lines.clone();
                out.remove(at);
                (out.join("\n").into_bytes(), format!("line {} deleted", at + 1))
            }
            3 if !lines.is_empty() => {
                let at = self.below(lines.len());
                let mut out = lines.clone();
                let copies = 1 + self.below(3);
                for _ in 0..copies {
                    out.insert(at, lines[at]);
                }
                (out.join("\n").into_bytes(), format!("line {} repeated {copies} times", at + 1))
            }
            4 if lines.len() > 1 => {
                let (a, b) = (self.below(lines.len()), self.below(lines.len()));
                let mut out = lines.clone();
                out.swap(a, b);
                (out.join("\n").into_bytes(), format!("lines {} and {} swapped", a + 1, b + 1))
            }
            5 | 6 => self.replace_number(&text),
            7 if !input.is_empty() => {
                let at = self.below(input.len());
                let mut out = input.to_vec();
                let bit = 1u8 << self.below(8);
                out[at] ^= bit;
                (out, format!("bit {bit:#04x} of byte {at} flipped"))
            }
            _ => {
                let at = self.below(input.len() + 1);
                let garbage: Vec<u8> = (0..1 + self.below(16)).map(|_| self.rng.next_u64() as u8).collect();
                let mut out = input[..at].to_vec();
                out.extend_from_slice(&garbage);
                out.extend_from_slice(&input[at..]);
                (out, format!("{} random bytes inserted at byte {at}", garbage.len()))
            }
        }
    }

    /// A number token of `text` (digits with sign, point, exponent) replaced by a hostile one.
    fn replace_number(&mut self, text: &str) -> (Vec<u8>, String) {
        let bytes = text.as_bytes();
        let mut spans = Vec::new();
        let mut i = 0;
        while i < bytes.len() {
            let starts = bytes[i].is_ascii_digit()
                || (matches!(bytes[i], b'-' | b'+' | b'.') && bytes.get(i + 1).is_some_and(u8::is_ascii_digit));
            if starts && (i == 0 || !bytes[i - 1].is_ascii_alphanumeric()) {
                let start = i;
                i += 1;
                while i < bytes.len()
                    && (bytes[i].is_ascii_digit() || matches!(bytes[i], b'.' | b'e' | b'E' | b'-' | b'+'))
                {
                    i += 1;
                }
                spans.push((start, i));
            } else {
                i += 1;
            }
        }
        if spans.is_empty() {
            return (text.as_bytes().to_vec(), "unchanged (no number)".into());
        }
        let (a, b) = spans[self.below(spans.len())];
        let with = HOSTILE_NUMBERS[self.below(HOSTILE_NUMBERS.len())];
        let out = format!("{}{with}{}", &text[..a], &text[b..]);
        (out.into_bytes(), format!("number '{}' at byte {a} replaced by '{with}'", &text[a..b]))
    }
}
