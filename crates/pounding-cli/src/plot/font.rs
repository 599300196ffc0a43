//! Text metrics of the figures' font, DejaVu Sans (`assets/DejaVuSans-subset.ttf`), for layout: legend boxes,
//! margins for tick labels. Read once from the font's `hmtx` table with fonttools; 2048 units per em.

/// Advance widths of the printable ASCII characters U+0020 to U+007E, font units (2048 per em).
const ASCII_ADVANCE: [u16; 95] = [
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690, 1303,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716, 1087, 2048,
    1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767, 1532, 1612, 1235,
    1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690, 799, 1716, 1024, 1024,
    1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186, 569, 1995, 1298, 1253, 1300,
    1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075, 1303, 690, 1303, 1716,
];

/// Width of `text` set at `size` px, px. Characters outside ASCII count as a digit's width, except the
/// math symbols the figures use (minus, times, comparison signs), which are as wide as `+`.
pub fn text_width(text: &str, size: f64) -> f64 {
    let units: u32 = text
        .chars()
        .map(|c| match c as u32 {
            0x20..=0x7e => u32::from(ASCII_ADVANCE[(c as u32 - 0x20) as usize]),
            0x2212 | 0xd7 | 0x2264 | 0x2265 | 0x2248 | 0x2260 => 1716,
            _ => 1303,
        })
        .sum();
    f64::from(units) / 2048.0 * size
}

#[cfg(test)]
mod tests {
    #[test]
    fn digits_are_about_two_thirds_of_an_em() {
        assert!((super::text_width("0", 12.0) - 12.0 * 1303.0 / 2048.0).abs() < 1e-12);
        assert!(super::text_width("WWW", 10.0) > super::text_width("iii", 10.0) * 3.0);
    }
}
