//! A window of the full image (`--crop`): the camera and the full size stay, only the
//! window's pixels are rendered and stored.

/// Pixels `x0..x1` x `y0..y1` of the full image (row 0 on top; ends exclusive).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Crop {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl Crop {
    /// The whole image.
    pub fn full(width: u32, height: u32) -> Crop {
        Crop { x0: 0, y0: 0, x1: width, y1: height }
    }
    pub fn width(&self) -> u32 {
        self.x1 - self.x0
    }
    pub fn height(&self) -> u32 {
        self.y1 - self.y0
    }
    pub fn pixels(&self) -> u64 {
        self.width() as u64 * self.height() as u64
    }
    /// Whether the window is non-empty and lies inside a `width` x `height` image.
    pub fn check(&self, width: u32, height: u32) -> Result<(), String> {
        if self.x0 >= self.x1 || self.y0 >= self.y1 {
            return Err(format!("crop {self} is empty (X0 < X1 and Y0 < Y1 needed)"));
        }
        if self.x1 > width || self.y1 > height {
            return Err(format!("crop {self} reaches outside the {width}x{height} image"));
        }
        Ok(())
    }
    /// Whether two windows share a pixel.
    pub fn overlaps(&self, o: &Crop) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
    /// The smallest window holding both.
    pub fn union(&self, o: &Crop) -> Crop {
        Crop { x0: self.x0.min(o.x0), y0: self.y0.min(o.y0), x1: self.x1.max(o.x1), y1: self.y1.max(o.y1) }
    }
}

impl std::fmt::Display for Crop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{},{},{},{}", self.x0, self.y0, self.x1, self.y1)
    }
}

impl std::str::FromStr for Crop {
    type Err = String;
    /// `X0,Y0,X1,Y1`.
    fn from_str(s: &str) -> Result<Crop, String> {
        let v: Vec<u32> = s
            .split(',')
            .map(|t| t.trim().parse::<u32>())
            .collect::<Result<_, _>>()
            .map_err(|_| format!("crop '{s}' is not X0,Y0,X1,Y1 (four pixel numbers)"))?;
        match v[..] {
            [x0, y0, x1, y1] => Ok(Crop { x0, y0, x1, y1 }),
            _ => Err(format!("crop '{s}' is not X0,Y0,X1,Y1 (four pixel numbers)")),
        }
    }
}

/// Sample indices `start..end` of every pixel (`--sample-range`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SampleRange {
    pub start: u32,
    pub end: u32,
}

impl SampleRange {
    pub fn len(&self) -> u32 {
        self.end - self.start
    }
    pub fn is_empty(&self) -> bool {
        self.end <= self.start
    }
}

impl std::fmt::Display for SampleRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

impl std::str::FromStr for SampleRange {
    type Err = String;
    /// `START..END` (END exclusive, START < END).
    fn from_str(s: &str) -> Result<SampleRange, String> {
        let bad = || format!("sample range '{s}' is not START..END with START < END (e.g. 0..64)");
        let (a, b) = s.split_once("..").ok_or_else(bad)?;
        let (start, end) = (a.trim().parse::<u32>().map_err(|_| bad())?, b.trim().parse::<u32>().map_err(|_| bad())?);
        if start >= end {
            return Err(bad());
        }
        Ok(SampleRange { start, end })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn parse_and_check() {
        let c: Crop = "0,8,16,32".parse().unwrap();
        assert_eq!(c, Crop { x0: 0, y0: 8, x1: 16, y1: 32 });
        assert_eq!((c.width(), c.height()), (16, 24));
        assert!(c.check(16, 32).is_ok());
        assert!(c.check(15, 32).is_err());
        assert!("4,4,4,8".parse::<Crop>().unwrap().check(16, 16).is_err());
        assert!("1,2,3".parse::<Crop>().is_err());
        assert!("a,2,3,4".parse::<Crop>().is_err());
        assert!(c.overlaps(&"15,31,20,40".parse().unwrap()));
        assert!(!c.overlaps(&"16,0,20,40".parse().unwrap()));
        let r: SampleRange = "8..24".parse().unwrap();
        assert_eq!((r.start, r.end, r.len()), (8, 24, 16));
        assert!("8..8".parse::<SampleRange>().is_err());
        assert!("8-9".parse::<SampleRange>().is_err());
        assert_eq!(r.to_string().parse::<SampleRange>().unwrap(), r);
    }
}
