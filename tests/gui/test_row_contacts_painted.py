"""Delta's edge and comparison contacts in the console: painted as contacts with their mark
and operands, and the diagnostic view's power flow shows through them (cell_map)."""

from __future__ import annotations

from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtWidgets import QApplication, QStyleOptionGraphicsItem

from ladderworks.core.compiler import compile, decode
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Contact, LadderNetwork
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.gui.docks.cell_map import binary_networks, cell_ops, network_power
from ladderworks.gui.editor.network_item import NetworkItem
from tests.core.dialects.conftest import delta, put

TEXT = "LD X1\nAND= D0 K5\nOUT Y1\nLD X2\nORP X3\nOUT Y2\nEND\n"


def _image(item: NetworkItem) -> QImage:
    rect = item.boundingRect()
    image = QImage(int(rect.width()), int(rect.height()), QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    option = QStyleOptionGraphicsItem()
    option.exposedRect = rect
    item.paint(painter, option, None)
    painter.end()
    return image


def _item(network: LadderNetwork) -> NetworkItem:
    item = NetworkItem(network, 1, lambda _address: None)
    item.spelling = spelling("delta")
    return item


def test_a_comparison_contact_is_painted_with_its_operator_and_operands(
        qapp: QApplication) -> None:
    net = layout_network(delta(TEXT).networks[0].instructions)
    contact = net.cells[(0, 1)]
    assert isinstance(contact, Contact) and contact.function
    item = _item(net)
    address, below, _ = item.label_lines(contact)
    assert (address, below) == ("D0", "K5")
    plain = net.copy()
    plain.cells[(0, 1)] = Contact(net.cells[(0, 0)].address)  # type: ignore[union-attr]
    drawn, without = _image(item), _image(_item(plain))
    assert drawn.size() == without.size()
    assert drawn != without  # the `=` inside and the operands differ from a plain contact


def test_power_flows_through_a_comparison_contact_when_it_passes() -> None:
    program = delta(TEXT)
    plc = ScanEngine(compile(program))
    binary = decode(compile(program))
    plc.monitored = True
    net = layout_network(program.networks[0].instructions)
    ops = binary_networks(binary)[0]
    cells = cell_ops(net, ops, binary)
    assert (0, 1) in cells  # the AND= op is mapped to the contact's cell
    put(plc, "X1", 1)
    for value, closed in ((4, False), (5, True)):
        put(plc, "D0", value)
        plc.scan()
        power = network_power(net, plc.memory.bit, cells, flow=bytes(plc.power_flow))
        assert ((0, 1) in power.closed) is closed, value
        assert ((0, net.coil_column) in power.coils) is closed


def test_the_live_ladder_matches_a_delta_program_with_branches_and_row_contacts() -> None:
    from ladderworks.core.ladder.convert import program_to_ladder
    from ladderworks.gui.docks.live_ladder import match_networks
    program = delta("LD X0\nMPS\nAND X1\nOUT Y0\nMPP\nAND= D0 K5\nOUT Y1\n" + TEXT)
    networks = program_to_ladder(program).networks
    assert all(net.listing is None for net in networks[:-1])  # END is a box of its own
    groups = match_networks(networks, decode(compile(program)))
    assert groups is not None and len(groups[0]) == 7  # RD MPS AND WRT MPP AND= WRT
    cells = cell_ops(networks[0], groups[0], decode(compile(program)))
    assert len(cells) == 5  # the contacts and coils; MPS / MPP have no cell
