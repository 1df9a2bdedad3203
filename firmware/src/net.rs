//! The network path: GEM0 under smoltcp (IPv4, DHCP with a static
//! fallback), and the socketcand server on TCP port
//! `drive::can_gateway::PORT` in front of the drive's CANopen device
//! (`crate::fieldbus`). Polled from the console loop (`app`), never from
//! an interrupt: the control interrupt only hands the device the servo
//! after each step (`drive::fieldbus::Link::boundary`), and a poll only
//! moves what is there, so it never waits for the network.
use crate::ps::gem::Gem;
use drive::can_gateway::{Device, Gateway, LineSink, PORT};
use smoltcp::iface::{
    Config, Interface, PollIngressSingleResult, PollResult, SocketHandle, SocketSet, SocketStorage,
};
use smoltcp::socket::{dhcpv4, tcp};
use smoltcp::time::Instant;
use smoltcp::wire::{EthernetAddress, IpCidr, Ipv4Address, Ipv4Cidr};

/// Station address: locally administered (bit 1 of the first byte),
/// unicast.
const MAC: [u8; 6] = [0x02, 0x5D, 0x00, 0x00, 0x00, 0x01];
/// Address used until (and unless) a DHCP server answers: QEMU's user
/// network gives the guest 10.0.2.15/24 behind 10.0.2.2.
const STATIC_ADDR: Ipv4Cidr = Ipv4Cidr::new(Ipv4Address::new(10, 0, 2, 15), 24);
const STATIC_GATEWAY: Ipv4Address = Ipv4Address::new(10, 0, 2, 2);
/// TCP receive and transmit buffers of the socketcand connection, bytes:
/// a few dozen commands or frame lines each.
const TCP_BUF: usize = 2048;
/// Received bytes handed to the gateway per step.
const CHUNK: usize = 256;
/// Received Ethernet frames handled per pass: the receive ring's size.
const MAX_FRAMES_IN: usize = 8;

static mut SOCKETS: [SocketStorage<'static>; 2] = [SocketStorage::EMPTY; 2];
static mut TCP_RX: [u8; TCP_BUF] = [0; TCP_BUF];
static mut TCP_TX: [u8; TCP_BUF] = [0; TCP_BUF];

/// The interface, its sockets and the CANopen node.
pub struct Net {
    gem: Gem,
    iface: Interface,
    sockets: SocketSet<'static>,
    tcp: SocketHandle,
    dhcp: SocketHandle,
    gateway: Gateway,
    /// Whether the address came from DHCP.
    leased: bool,
}

/// The socketcand connection as the gateway writes to it: whole lines
/// or nothing.
struct Sink<'a>(&'a mut tcp::Socket<'static>);

impl LineSink for Sink<'_> {
    fn send(&mut self, line: &[u8]) -> bool {
        let s = &mut *self.0;
        if !s.may_send() || s.send_capacity() - s.send_queue() < line.len() {
            return false;
        }
        s.send_slice(line) == Ok(line.len())
    }
}

/// The drive's CANopen device (`crate::fieldbus`) as the gateway's
/// device: frames in with the servo, timed frames and those the control
/// interrupt left.
struct DriveDevice;

impl Device for DriveDevice {
    fn on_frame(&mut self, f: &canopen::CanFrame) -> canopen::Frames {
        crate::fieldbus::on_frame(f)
    }

    fn tick(&mut self, now_us: u64) -> canopen::Frames {
        let mut out = crate::fieldbus::take_from_control();
        out.append(&crate::fieldbus::tick(now_us));
        out
    }
}

fn instant(now_us: u64) -> Instant {
    Instant::from_micros(now_us as i64)
}

fn set_address(iface: &mut Interface, cidr: Ipv4Cidr, gateway: Option<Ipv4Address>) {
    iface.update_ip_addrs(|addrs| {
        addrs.clear();
        // One address into an empty list of two: cannot fail.
        let _ = addrs.push(IpCidr::Ipv4(cidr));
    });
    let routes = iface.routes_mut();
    routes.remove_default_ipv4_route();
    if let Some(gw) = gateway {
        // One route into an empty table: cannot fail.
        let _ = routes.add_default_ipv4_route(gw);
    }
}

impl Net {
    /// Starts GEM0, the interface and the server. Call once.
    pub fn init(now_us: u64, seed: u64) -> Self {
        let mut gem = Gem::init(MAC);
        let mut config = Config::new(EthernetAddress(MAC).into());
        config.random_seed = seed;
        let mut iface = Interface::new(config, &mut gem, instant(now_us));
        set_address(&mut iface, STATIC_ADDR, Some(STATIC_GATEWAY));
        // SAFETY: `init` runs once (from `app::main`), so these are the
        // only references to the statics.
        let (storage, rx, tx) = unsafe {
            (
                &mut *core::ptr::addr_of_mut!(SOCKETS),
                &mut *core::ptr::addr_of_mut!(TCP_RX),
                &mut *core::ptr::addr_of_mut!(TCP_TX),
            )
        };
        let mut sockets = SocketSet::new(&mut storage[..]);
        let mut socket = tcp::Socket::new(
            tcp::SocketBuffer::new(&mut rx[..]),
            tcp::SocketBuffer::new(&mut tx[..]),
        );
        // Each frame line goes out at once (no Nagle: a TPDO line does not
        // wait for the acknowledgement of the line before it, which a
        // client's delayed ACK holds for up to 40 ms), and each segment is
        // acknowledged at once, so a client's small writes do not wait on
        // ours.
        socket.set_nagle_enabled(false);
        socket.set_ack_delay(None);
        let tcp = sockets.add(socket);
        // Listening before the first poll: a client that connects as soon
        // as the banner is out finds the port open, not reset.
        let _ = sockets.get_mut::<tcp::Socket>(tcp).listen(PORT);
        let dhcp = sockets.add(dhcpv4::Socket::new());
        defmt::info!(
            "net: GEM0 up, static 10.0.2.15/24 until a DHCP lease, socketcand on TCP {=u16}",
            PORT
        );
        Self {
            gem,
            iface,
            sockets,
            tcp,
            dhcp,
            gateway: Gateway::new(),
            leased: false,
        }
    }

    /// What `status` shows.
    pub fn status(&self) -> drive::console::NetStatus {
        // IPv4 is the only protocol built in: the one address is one.
        let ipv4 = self.iface.ip_addrs().first().map(|c| match c {
            IpCidr::Ipv4(c) => (c.address().octets(), c.prefix_len()),
        });
        drive::console::NetStatus {
            ipv4,
            dhcp: self.leased,
            client: self.gateway.connected(),
            can: self.gateway.counts(),
        }
    }

    /// One pass: frames in and out, DHCP, the connection's bytes. Bounded:
    /// at most [`MAX_FRAMES_IN`] received frames, so that a flood of
    /// frames cannot hold the console loop (the rest wait in the ring).
    pub fn poll(&mut self, now_us: u64) {
        let t = instant(now_us);
        self.iface.poll_maintenance(t);
        for _ in 0..MAX_FRAMES_IN {
            let r = self
                .iface
                .poll_ingress_single(t, &mut self.gem, &mut self.sockets);
            if r == PollIngressSingleResult::None {
                break;
            }
        }
        self.dhcp_events();
        self.serve(now_us);
        // What the server and DHCP wrote goes out now, not on the next
        // pass (egress is bounded by the sockets' queued data).
        while self.iface.poll_egress(t, &mut self.gem, &mut self.sockets) != PollResult::None {}
    }

    fn dhcp_events(&mut self) {
        let event = self.sockets.get_mut::<dhcpv4::Socket>(self.dhcp).poll();
        match event {
            Some(dhcpv4::Event::Configured(c)) => {
                let a = c.address.address().octets();
                defmt::info!(
                    "net: DHCP lease {=u8}.{=u8}.{=u8}.{=u8}/{=u8}",
                    a[0],
                    a[1],
                    a[2],
                    a[3],
                    c.address.prefix_len()
                );
                let (address, router) = (c.address, c.router);
                set_address(&mut self.iface, address, router);
                self.leased = true;
            }
            Some(dhcpv4::Event::Deconfigured) => {
                if self.leased {
                    defmt::warn!("net: DHCP lease lost, back to the static address");
                }
                set_address(&mut self.iface, STATIC_ADDR, Some(STATIC_GATEWAY));
                self.leased = false;
            }
            None => {}
        }
    }

    fn serve(&mut self, now_us: u64) {
        let sock = self.sockets.get_mut::<tcp::Socket>(self.tcp);
        if !sock.is_open() {
            // Closed (never opened, or the last client gone): listen
            // again. The port is a valid endpoint: cannot fail.
            let _ = sock.listen(PORT);
        }
        let established = sock.state() == tcp::State::Established;
        if established && !self.gateway.connected() {
            defmt::info!("net: socketcand client connected");
            let hi = self.gateway.connect();
            let _ = Sink(sock).send(hi);
        } else if !established && self.gateway.connected() {
            // The client closed its side (or the connection broke): close
            // ours, so that the socket returns to listening.
            defmt::info!("net: socketcand client gone");
            self.gateway.disconnect();
            sock.close();
        }
        let mut buf = [0u8; CHUNK];
        while self.gateway.connected() && sock.can_recv() {
            let n = sock.recv_slice(&mut buf).unwrap_or(0);
            if n == 0 {
                break;
            }
            self.gateway
                .on_input(&buf[..n], now_us, &mut DriveDevice, &mut Sink(sock));
        }
        self.gateway.tick(now_us, &mut DriveDevice, &mut Sink(sock));
    }
}
