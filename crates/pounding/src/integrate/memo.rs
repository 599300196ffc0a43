//! What the builders of exact propagation make (a step length's transition rows, a whole interval's form
//! integrals, a functional's rows at its pieces' starts), kept per thread across runs and keyed by the exact
//! bits of every input: pure functions, so a result taken from here is the one a build would make, and no
//! choice of the engine depends on whether it was here. The runs of a study that keep a configuration (a
//! gap sweep's buildings, the same soil under every scale) build it once per worker thread instead of once
//! per run. Bounded in bytes ([`MEMO_BYTES`] per kind of result and thread), the least recently used
//! forgotten first.

use std::cell::RefCell;
use std::thread::LocalKey;

/// Most bytes of results of one kind a thread keeps (a storey on soil's whole-interval form integrals take
/// about 0.5 MB, a two-storey pair's transitions a few hundred bytes).
const MEMO_BYTES: usize = 8 << 20;

/// Most results of one kind a thread keeps: a lookup and a making of room read every entry, and a study that
/// changes its structures in every run (a stiffness axis) misses every time; 256 entries take about a
/// thousand instructions to read, where 8 MiB of a two-storey pair's transitions (10,000 entries) would take
/// thirty thousand per build.
const MEMO_ENTRIES: usize = 256;

/// The exact inputs of a build, bit for bit.
#[derive(Default)]
pub(crate) struct Key(Vec<u64>);

impl Key {
    /// A number's bits.
    pub(crate) fn num(mut self, x: f64) -> Self {
        self.0.push(x.to_bits());
        self
    }

    /// A count.
    pub(crate) fn count(mut self, n: usize) -> Self {
        self.0.push(n as u64);
        self
    }

    /// A slice's length and bits.
    pub(crate) fn slice(mut self, xs: &[f64]) -> Self {
        self.0.push(xs.len() as u64);
        self.0.extend(xs.iter().map(|x| x.to_bits()));
        self
    }

    fn digest(&self) -> u64 {
        // A multiply-rotate mix: the full key is compared on a match, so this only has to spread.
        self.0.iter().fold(0x9e37_79b9_7f4a_7c15, |h, &x| {
            (h ^ x).wrapping_mul(0x100_0000_01b3).rotate_left(29)
        })
    }
}

/// Results of one kind, with their keys.
pub(crate) struct Memo<V> {
    entries: Vec<Entry<V>>,
    bytes: usize,
    clock: u64,
}

struct Entry<V> {
    digest: u64,
    key: Key,
    value: V,
    bytes: usize,
    used: u64,
}

impl<V> Memo<V> {
    pub(crate) const fn new() -> Self {
        Self {
            entries: Vec::new(),
            bytes: 0,
            clock: 0,
        }
    }
}

/// The result for `key` from `memo` (this thread's), else `build()`'s, kept if it fits; `bytes` is a result's
/// size.
pub(crate) fn remembered<V: Clone + 'static>(
    memo: &'static LocalKey<RefCell<Memo<V>>>,
    key: Key,
    bytes: impl Fn(&V) -> usize,
    build: impl FnOnce() -> V,
) -> V {
    let digest = key.digest();
    let found = memo.with_borrow_mut(|m| {
        m.clock += 1;
        let now = m.clock;
        let e = m
            .entries
            .iter_mut()
            .find(|e| e.digest == digest && e.key.0 == key.0)?;
        e.used = now;
        Some(e.value.clone())
    });
    if let Some(v) = found {
        return v;
    }
    let value = build();
    let size = bytes(&value) + 8 * key.0.len();
    if size <= MEMO_BYTES {
        memo.with_borrow_mut(|m| {
            while m.bytes + size > MEMO_BYTES || m.entries.len() >= MEMO_ENTRIES {
                let oldest = (0..m.entries.len()).min_by_key(|&i| m.entries[i].used);
                let Some(i) = oldest else { break };
                m.bytes -= m.entries.swap_remove(i).bytes;
            }
            m.bytes += size;
            let used = m.clock;
            m.entries.push(Entry {
                digest,
                key,
                value: value.clone(),
                bytes: size,
                used,
            });
        });
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    thread_local! {
        static SQUARES: RefCell<Memo<Vec<f64>>> = const { RefCell::new(Memo::new()) };
    }

    #[test]
    fn a_result_is_built_once_per_key_and_the_oldest_goes_when_full() {
        let builds = std::cell::Cell::new(0);
        let square = |x: f64, len: usize| {
            remembered(
                &SQUARES,
                Key::default().num(x).count(len),
                |v: &Vec<f64>| 8 * v.len(),
                || {
                    builds.set(builds.get() + 1);
                    vec![x * x; len]
                },
            )
        };
        assert_eq!(square(3.0, 2), vec![9.0, 9.0]);
        assert_eq!(square(3.0, 2), vec![9.0, 9.0]);
        assert_eq!(square(-3.0, 2), vec![9.0, 9.0]);
        assert_eq!(builds.get(), 2, "one build per distinct key");
        // -0 and 0 are different bits: different inputs to a pure function may not share a result.
        square(0.0, 1);
        square(-0.0, 1);
        assert_eq!(builds.get(), 4);
        // Results that fill the memo push the least recently used out: two of these fit, three do not.
        let big = (MEMO_BYTES / 2 - 1024) / 8;
        square(1.0, big);
        square(2.0, big);
        square(1.0, big); // used again: 2.0's is now the oldest
        square(4.0, big);
        let before = builds.get();
        square(1.0, big);
        assert_eq!(builds.get(), before, "kept: recently used");
        square(2.0, big);
        assert_eq!(builds.get(), before + 1, "forgotten: the oldest");
        // Too big to keep at all: built every time.
        square(5.0, MEMO_BYTES / 8 + 1);
        square(5.0, MEMO_BYTES / 8 + 1);
        assert_eq!(builds.get(), before + 3);
        // Small results beyond the count push the oldest out too.
        square(6.0, 1);
        (0..MEMO_ENTRIES).for_each(|k| {
            square(100.0 + k as f64, 1);
        });
        let before = builds.get();
        square(6.0, 1);
        assert_eq!(
            builds.get(),
            before + 1,
            "forgotten: more entries than allowed"
        );
    }
}
