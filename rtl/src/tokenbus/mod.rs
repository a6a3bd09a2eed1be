//! # tokenbus
//!
//! The IEEE 802.4 Dual Channel Manager of the PICNET paper: the DCM and the redundancy management blocks (RMM) of one token-bus station.
//!
//! - [`dcm`]: IEEE 802.4 Dual Channel Manager (transmit on both, receive from the active channel, channel status)
//! - [`dcm_station`]: one token-bus station's DCM + RMM (`merkur_dcm_station`)
//! - [`rmm_detect`]: RMM fault detection from the six MAC events (SC, NS)
//! - [`rmm_fcm`]: RMM fault correction machine (five states)
//! - [`rmm_sfc`]: RMM status frame check (3 bytes per station in block RAM)
//! - [`rmm_sfp`]: RMM status frame production (live counter, status byte)

pub mod dcm;
pub mod dcm_station;
pub mod rmm_detect;
pub mod rmm_fcm;
pub mod rmm_sfc;
pub mod rmm_sfp;
