//! Text metrics of the figures' font, DejaVu Sans (`assets/DejaVuSans-subset.ttf`), for layout: legend boxes,
//! margins for tick labels, titles. Read from the `hmtx` tables of DejaVu Sans and DejaVu Sans Bold 2.37
//! (`fonts-dejavu-core`); 2048 units per em.

/// Advance widths of the printable ASCII characters U+0020 to U+007E, font units (2048 per em).
const ASCII_ADVANCE: [u16; 95] = [
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690, 1303,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716, 1087, 2048,
    1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767, 1532, 1612, 1235,
    1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690, 799, 1716, 1024, 1024,
    1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186, 569, 1995, 1298, 1253, 1300,
    1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075, 1303, 690, 1303, 1716,
];

/// The same for DejaVu Sans Bold (figure titles are bold: a browser sets them in the bold face).
const BOLD_ASCII_ADVANCE: [u16; 95] = [
    713, 934, 1067, 1716, 1425, 2052, 1786, 627, 936, 936, 1071, 1716, 778, 850, 778, 748, 1425,
    1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 1425, 819, 819, 1716, 1716, 1716, 1188, 2048,
    1585, 1561, 1503, 1700, 1399, 1399, 1681, 1714, 762, 762, 1587, 1305, 2038, 1714, 1741, 1501,
    1741, 1577, 1475, 1397, 1663, 1585, 2259, 1579, 1483, 1485, 936, 748, 936, 1716, 1024, 1024,
    1382, 1466, 1214, 1466, 1389, 891, 1466, 1458, 702, 702, 1362, 702, 2134, 1458, 1407, 1466,
    1466, 1010, 1219, 979, 1458, 1335, 1892, 1321, 1335, 1192, 1458, 748, 1458, 1716,
];

/// Width of `text` set at `size` px, px. Characters outside ASCII count as a digit's width, except the
/// math symbols the figures use (minus, times, plus-minus, comparison signs), which are as wide as `+`, and
/// the ellipsis and the em dash, an em.
pub fn text_width(text: &str, size: f64) -> f64 {
    width_in(&ASCII_ADVANCE, 1303, text, size)
}

/// Width of `text` set in bold at `size` px, px (the same rules as [`text_width`], in the bold face).
pub fn bold_text_width(text: &str, size: f64) -> f64 {
    width_in(&BOLD_ASCII_ADVANCE, 1425, text, size)
}

fn width_in(ascii: &[u16; 95], digit: u32, text: &str, size: f64) -> f64 {
    let units: u32 = text
        .chars()
        .map(|c| match c as u32 {
            0x20..=0x7e => u32::from(ascii[(c as u32 - 0x20) as usize]),
            0x2212 | 0xd7 | 0xb1 | 0x2264 | 0x2265 | 0x2248 | 0x2260 => 1716,
            0x2026 | 0x2014 => 2048,
            _ => digit,
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

    #[test]
    fn bold_is_wider() {
        // DejaVu Sans Bold's "W" is 2259 units, the regular's 2025.
        assert!((super::bold_text_width("W", 2048.0) - 2259.0).abs() < 1e-9);
        let t = "Force against penetration of the strongest impacts";
        assert!(super::bold_text_width(t, 16.0) > 1.08 * super::text_width(t, 16.0));
    }
}
