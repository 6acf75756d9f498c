//! `now` and `datetime(days [, format])`: times as days since 2000-01-01 00:00 UTC.
//!
//! In: a day count and a strftime-style format. Out: the formatted UTC time, or a message
//! saying why the format or the date cannot be used. Holds: the output matches what POV-Ray
//! 3.7 prints (through the C library's `strftime` in the "C" locale), without a time crate.

use std::time::{SystemTime, UNIX_EPOCH};

/// The format `datetime` uses when none is given.
pub const DEFAULT_FORMAT: &str = "%Y-%m-%d %H:%M:%SZ";
/// Longest format string accepted.
const FORMAT_LIMIT: usize = 200;
/// Longest result accepted.
const RESULT_LIMIT: usize = 199;
/// Days from 1970-01-01 to 2000-01-01.
const DAYS_1970_TO_2000: i64 = 10_957;
/// Years POV-Ray accepts.
const YEARS: std::ops::RangeInclusive<i64> = 1400..=9999;

const WEEKDAYS: [&str; 7] = [
    "Sunday",
    "Monday",
    "Tuesday",
    "Wednesday",
    "Thursday",
    "Friday",
    "Saturday",
];
const MONTHS: [&str; 12] = [
    "January",
    "February",
    "March",
    "April",
    "May",
    "June",
    "July",
    "August",
    "September",
    "October",
    "November",
    "December",
];

/// The current time in days since 2000-01-01 00:00 UTC (the value of `now`).
pub fn now_in_days() -> f64 {
    let seconds = match SystemTime::now().duration_since(UNIX_EPOCH) {
        Ok(since) => since.as_secs_f64(),
        Err(before) => -before.duration().as_secs_f64(),
    };
    seconds / 86_400.0 - DAYS_1970_TO_2000 as f64
}

/// A broken-down UTC time.
#[derive(Clone, Copy)]
struct Civil {
    year: i64,
    /// 1 to 12.
    month: i64,
    /// 1 to 31.
    day: i64,
    hour: i64,
    minute: i64,
    second: i64,
    /// 0 (Sunday) to 6.
    weekday: i64,
    /// 0 to 365.
    year_day: i64,
    /// Seconds since 1970-01-01 00:00 UTC.
    unix_seconds: i64,
}

impl Civil {
    /// The time `days` after 2000-01-01 00:00 UTC, rounded to the nearest second.
    fn from_days(days: f64) -> Result<Civil, String> {
        let seconds = (days * 86_400.0).round();
        if !seconds.is_finite() || seconds.abs() > 1e15 {
            return Err(format!("{days} days is not a usable date"));
        }
        let unix_seconds = seconds as i64 + DAYS_1970_TO_2000 * 86_400;
        let day_number = unix_seconds.div_euclid(86_400);
        let second_of_day = unix_seconds.rem_euclid(86_400);
        let (year, month, day) = civil_from_days(day_number);
        if !YEARS.contains(&year) {
            return Err(format!(
                "year {year} is outside the range datetime accepts (1400 to 9999)"
            ));
        }
        let year_start = days_from_civil(year, 1, 1);
        Ok(Civil {
            year,
            month,
            day,
            hour: second_of_day / 3600,
            minute: second_of_day / 60 % 60,
            second: second_of_day % 60,
            // 1970-01-01 was a Thursday.
            weekday: (day_number + 4).rem_euclid(7),
            year_day: day_number - year_start,
            unix_seconds,
        })
    }

    /// ISO 8601 week-based year and week number.
    fn iso_week(&self) -> (i64, i64) {
        let iso_weekday = (self.weekday + 6) % 7; // Monday 0
        let week = (self.year_day - iso_weekday + 10) / 7;
        if week < 1 {
            let previous = self.year - 1;
            let days_in_previous =
                days_from_civil(self.year, 1, 1) - days_from_civil(previous, 1, 1);
            let shifted = Civil {
                year_day: self.year_day + days_in_previous,
                year: previous,
                ..*self
            };
            return shifted.iso_week();
        }
        let days_in_year = days_from_civil(self.year + 1, 1, 1) - days_from_civil(self.year, 1, 1);
        // Week 53 exists only when the year's last days reach a Thursday.
        if week == 53 && self.year_day - iso_weekday + 3 >= days_in_year {
            return (self.year + 1, 1);
        }
        (self.year, week)
    }
}

/// (year, month, day) of a day number counted from 1970-01-01 (proleptic Gregorian).
fn civil_from_days(days: i64) -> (i64, i64, i64) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let day_of_era = z.rem_euclid(146_097);
    let year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let shifted_month = (5 * day_of_year + 2) / 153;
    let day = day_of_year - (153 * shifted_month + 2) / 5 + 1;
    let month = if shifted_month < 10 {
        shifted_month + 3
    } else {
        shifted_month - 9
    };
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

/// Day number (from 1970-01-01) of a proleptic Gregorian date.
fn days_from_civil(year: i64, month: i64, day: i64) -> i64 {
    let year = if month <= 2 { year - 1 } else { year };
    let era = year.div_euclid(400);
    let year_of_era = year.rem_euclid(400);
    let shifted_month = if month > 2 { month - 3 } else { month + 9 };
    let day_of_year = (153 * shifted_month + 2) / 5 + day - 1;
    let day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
    era * 146_097 + day_of_era - 719_468
}

/// Formats `days` (since 2000-01-01 UTC) with a strftime-style `format`.
pub fn format_days(days: f64, format: &str) -> Result<String, String> {
    if format.is_empty() {
        return Err("the datetime format is empty".into());
    }
    if format.len() > FORMAT_LIMIT {
        return Err(format!(
            "the datetime format is longer than {FORMAT_LIMIT} characters"
        ));
    }
    let time = Civil::from_days(days)?;
    let mut out = String::new();
    let mut rest = format;
    while let Some(at) = rest.find('%') {
        out.push_str(&rest[..at]);
        let sequence = &rest[at..];
        let (text, length) = conversion_sequence(&time, sequence)?;
        out.push_str(&text);
        rest = &sequence[length..];
    }
    out.push_str(rest);
    if out.len() > RESULT_LIMIT {
        return Err(format!(
            "the formatted date is longer than {RESULT_LIMIT} characters"
        ));
    }
    Ok(out)
}

/// How a conversion pads numbers.
#[derive(Clone, Copy, PartialEq)]
enum Padding {
    /// The usual padding: zeros for most numbers, spaces for `%e`, `%k`, `%l`, `%s`.
    Usual,
    /// `%-d`: none.
    None,
    /// `%_d`: spaces.
    Spaces,
    /// `%0e`: zeros.
    Zeros,
}

/// The text of the conversion at the start of `sequence` (which starts with `%`) and the
/// length of the sequence. Flags (`-`, `_`, `0`), a minimum width and the `E`/`O`
/// modifiers are accepted, as the C library does; unknown sequences are copied as written.
fn conversion_sequence(time: &Civil, sequence: &str) -> Result<(String, usize), String> {
    let bytes = sequence.as_bytes();
    let mut at = 1;
    let mut padding = Padding::Usual;
    while let Some(flag) = bytes.get(at) {
        padding = match flag {
            b'-' => Padding::None,
            b'_' => Padding::Spaces,
            b'0' => Padding::Zeros,
            _ => break,
        };
        at += 1;
    }
    let width_start = at;
    while bytes.get(at).is_some_and(u8::is_ascii_digit) {
        at += 1;
    }
    // A width past the result limit fails that limit anyway; capping it keeps `format!` safe.
    let width = match &sequence[width_start..at] {
        "" => 0,
        digits => digits
            .parse::<usize>()
            .unwrap_or(usize::MAX)
            .min(RESULT_LIMIT + 1),
    };
    if matches!(bytes.get(at), Some(b'E' | b'O')) {
        at += 1;
    }
    let Some(code) = sequence[at..].chars().next() else {
        return Ok((sequence.to_string(), sequence.len()));
    };
    let length = at + code.len_utf8();
    Ok(match conversion(time, code, width, padding)? {
        Some(text) => (text, length),
        None => (sequence[..length].to_string(), length),
    })
}

/// The text of one conversion `%code` (with an optional minimum width), `None` when the
/// code is unknown.
fn conversion(
    time: &Civil,
    code: char,
    width: usize,
    padding: Padding,
) -> Result<Option<String>, String> {
    let padded = |value: i64, digits: usize, zeros: bool| {
        let w = width.max(digits);
        match (padding, zeros) {
            (Padding::None, _) => format!("{value:>width$}"),
            (Padding::Zeros, _) | (Padding::Usual, true) => format!("{value:0>w$}"),
            _ => format!("{value:>w$}"),
        }
    };
    let number = |value: i64, digits: usize| padded(value, digits, true);
    let spaced = |value: i64, digits: usize| padded(value, digits, false);
    let text = |s: &str| format!("{s:>width$}");
    let hour12 = (time.hour + 11) % 12 + 1;
    let weekday_name = WEEKDAYS[time.weekday as usize];
    let month_name = MONTHS[time.month as usize - 1];
    let sunday_week = (time.year_day + 7 - time.weekday) / 7;
    let monday_week = (time.year_day + 7 - (time.weekday + 6) % 7) / 7;
    Ok(Some(match code {
        'a' => text(&weekday_name[..3]),
        'A' => text(weekday_name),
        'b' | 'h' => text(&month_name[..3]),
        'B' => text(month_name),
        'c' => text(&format!(
            "{} {} {:>2} {:02}:{:02}:{:02} {}",
            &weekday_name[..3],
            &month_name[..3],
            time.day,
            time.hour,
            time.minute,
            time.second,
            time.year
        )),
        'C' => number(time.year / 100, 2),
        'd' => number(time.day, 2),
        'D' | 'x' => text(&format!(
            "{:02}/{:02}/{:02}",
            time.month,
            time.day,
            time.year % 100
        )),
        'e' => spaced(time.day, 2),
        'F' => text(&format!(
            "{:04}-{:02}-{:02}",
            time.year, time.month, time.day
        )),
        'g' => number(time.iso_week().0 % 100, 2),
        'G' => number(time.iso_week().0, 4),
        'H' => number(time.hour, 2),
        'I' => number(hour12, 2),
        'j' => number(time.year_day + 1, 3),
        'k' => spaced(time.hour, 2),
        'l' => spaced(hour12, 2),
        'm' => number(time.month, 2),
        'M' => number(time.minute, 2),
        'n' => "\n".into(),
        'p' => text(if time.hour < 12 { "AM" } else { "PM" }),
        'P' => text(if time.hour < 12 { "am" } else { "pm" }),
        'r' => text(&format!(
            "{:02}:{:02}:{:02} {}",
            hour12,
            time.minute,
            time.second,
            if time.hour < 12 { "AM" } else { "PM" }
        )),
        'R' => text(&format!("{:02}:{:02}", time.hour, time.minute)),
        's' => spaced(time.unix_seconds, 1),
        'S' => number(time.second, 2),
        't' => "\t".into(),
        'T' | 'X' => text(&format!(
            "{:02}:{:02}:{:02}",
            time.hour, time.minute, time.second
        )),
        'u' => number((time.weekday + 6) % 7 + 1, 1),
        'U' => number(sunday_week, 2),
        'V' => number(time.iso_week().1, 2),
        'w' => number(time.weekday, 1),
        'W' => number(monday_week, 2),
        'y' => number(time.year % 100, 2),
        'Y' => number(time.year, 1),
        '%' => "%".into(),
        'z' | 'Z' => {
            return Err(format!(
                "`%{code}` cannot be used: datetime has no time zone (it is always UTC)"
            ))
        }
        _ => return Ok(None),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2000-01-03 01:05:07 UTC.
    const MONDAY: f64 = 1.5 + 13.0 / 24.0 + 5.0 / 1440.0 + 7.0 / 86_400.0;

    #[test]
    fn the_default_format_matches_povray() {
        assert_eq!(
            format_days(0.0, DEFAULT_FORMAT).unwrap(),
            "2000-01-01 00:00:00Z"
        );
        assert_eq!(
            format_days(-400.25, DEFAULT_FORMAT).unwrap(),
            "1998-11-26 18:00:00Z"
        );
        // Rounded to the nearest second.
        assert_eq!(
            format_days(9000.999999, DEFAULT_FORMAT).unwrap(),
            "2024-08-23 00:00:00Z"
        );
        assert_eq!(
            format_days(59.5, DEFAULT_FORMAT).unwrap(),
            "2000-02-29 12:00:00Z"
        );
    }

    #[test]
    fn conversions_match_povray() {
        let cases = [
            ("%a %A %b %B", "Mon Monday Jan January"),
            ("%c", "Mon Jan  3 01:05:07 2000"),
            ("%d %H %I %j %m %M %p %S", "03 01 01 003 01 05 AM 07"),
            (
                "%U %w %W %x %X %y %Y %%",
                "01 1 01 01/03/00 01:05:07 00 2000 %",
            ),
            (
                "%e|%D|%F|%T|%R|%h",
                " 3|01/03/00|2000-01-03|01:05:07|01:05|Jan",
            ),
            (
                "%k|%l|%P|%C|%g|%G|%u|%V|%s",
                " 1| 1|am|20|00|2000|1|01|946861507",
            ),
            ("%q %E %Ey %Oy %+ %5Y abc%", "%q %E 00 00 %+ 02000 abc%"),
            ("%E|%-d|%_d|%0e", "%E|3| 3|03"),
        ];
        for (format, expected) in cases {
            assert_eq!(format_days(MONDAY, format).unwrap(), expected, "{format}");
        }
    }

    #[test]
    fn bad_formats_and_dates_are_refused() {
        assert!(format_days(0.0, "").is_err());
        assert!(format_days(0.0, "%Z").is_err());
        assert!(format_days(0.0, &"%c".repeat(45)).is_err());
        assert!(format_days(1e7, DEFAULT_FORMAT).is_err());
        assert!(format_days(f64::NAN, DEFAULT_FORMAT).is_err());
    }

    #[test]
    fn iso_weeks_cross_year_ends() {
        // 2000-01-01 (a Saturday) belongs to week 52 of 1999; 2004-12-31 to week 53 of 2004.
        assert_eq!(format_days(0.0, "%G-%V").unwrap(), "1999-52");
        // Widths far past the limit fail it, never panic.
        assert!(format_days(0.0, "%70000d").is_err());
        assert!(format_days(0.0, "%99999999999999999999999d").is_err());
        let last_of_2004 = (days_from_civil(2004, 12, 31) - DAYS_1970_TO_2000) as f64;
        assert_eq!(format_days(last_of_2004, "%G-%V").unwrap(), "2004-53");
        let last_of_2001 = (days_from_civil(2001, 12, 31) - DAYS_1970_TO_2000) as f64;
        assert_eq!(format_days(last_of_2001, "%G-%V").unwrap(), "2002-01");
    }
}
