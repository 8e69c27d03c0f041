-- Omron Host Link (C-mode and FINS over Host Link) for Wireshark and tshark.
--
-- Decodes the captures hostlink writes (monitor-line --capture, a client's TraceFile, simulate --capture): pcap link
-- type 147 (LINKTYPE_USER0) whose records start with a 12-byte header: "H" "L", version 1, the direction (0 unknown,
-- 1 host to PLC, 2 PLC to host), flags (1: the UART reported a line error, 2: bytes that do not frame), three zero
-- bytes, and the microseconds from the record's first byte to its last (big-endian). Also registered for TCP port
-- 4001 (a serial-device server's raw TCP port; change it in the protocol's preferences or with
-- -o hostlink.tcp_port:N), where frames are cut at each CR and the server's side is the PLC.
--
-- Each frame shows its unit, header (the command), end code, text and FCS (found, expected, good or bad: a bad one is
-- an expert error). A later frame of a divided command or answer (no "@") is tied to its first frame; the bare CR that
-- asks for the next frame is shown as such. FA frames show the FINS header, command code and response code.
--
-- Use: tshark -X lua_script:tools/wireshark/omron-hostlink.lua -r capture.pcap
--      (or copy this file to ~/.local/lib/wireshark/plugins/ for Wireshark).
-- Fields: hostlink.direction, hostlink.unit, hostlink.header, hostlink.name, hostlink.end_code,
--         hostlink.end_code.meaning, hostlink.fcs, hostlink.fcs.expected, hostlink.fcs.status ("good"/"bad"),
--         hostlink.kind, hostlink.final, hostlink.first_frame, hostlink.fins.command, hostlink.fins.response_code.

local hostlink = Proto("hostlink", "Omron Host Link")

local directions = { [0] = "unknown", [1] = "host to PLC", [2] = "PLC to host" }

local pf = {
    direction = ProtoField.uint8("hostlink.direction", "Direction", base.DEC, directions),
    flags = ProtoField.uint8("hostlink.flags", "Record flags", base.HEX),
    duration = ProtoField.uint32("hostlink.duration_us", "First to last byte (us)", base.DEC),
    kind = ProtoField.string("hostlink.kind", "Frame"),
    unit = ProtoField.uint8("hostlink.unit", "Unit", base.DEC),
    header = ProtoField.string("hostlink.header", "Header"),
    name = ProtoField.string("hostlink.name", "Command"),
    end_code = ProtoField.string("hostlink.end_code", "End code"),
    end_code_meaning = ProtoField.string("hostlink.end_code.meaning", "End code meaning"),
    text = ProtoField.string("hostlink.text", "Text"),
    fcs = ProtoField.string("hostlink.fcs", "FCS"),
    fcs_expected = ProtoField.string("hostlink.fcs.expected", "FCS expected"),
    fcs_status = ProtoField.string("hostlink.fcs.status", "FCS status"),
    final = ProtoField.bool("hostlink.final", "Final frame (*CR)"),
    first_frame = ProtoField.framenum("hostlink.first_frame", "First frame of this message"),
    fins_wait = ProtoField.string("hostlink.fins.wait", "FINS response wait (10 ms units)"),
    fins_icf = ProtoField.string("hostlink.fins.icf", "FINS ICF"),
    fins_da2 = ProtoField.string("hostlink.fins.da2", "FINS DA2"),
    fins_sa2 = ProtoField.string("hostlink.fins.sa2", "FINS SA2"),
    fins_sid = ProtoField.string("hostlink.fins.sid", "FINS SID"),
    fins_command = ProtoField.string("hostlink.fins.command", "FINS command code"),
    fins_command_name = ProtoField.string("hostlink.fins.command.name", "FINS command"),
    fins_response_code = ProtoField.string("hostlink.fins.response_code", "FINS response code"),
    fins_response_meaning = ProtoField.string("hostlink.fins.response_code.meaning", "FINS response"),
    fins_data = ProtoField.string("hostlink.fins.data", "FINS data"),
}
hostlink.fields = pf

local expert_bad_fcs = ProtoExpert.new("hostlink.fcs.bad.expert", "Bad FCS", expert.group.CHECKSUM, expert.severity.ERROR)
local expert_line_error = ProtoExpert.new("hostlink.line_error.expert", "The UART reported a line error", expert.group.MALFORMED, expert.severity.WARN)
local expert_noise = ProtoExpert.new("hostlink.noise.expert", "Bytes that do not frame", expert.group.MALFORMED, expert.severity.WARN)
hostlink.experts = { expert_bad_fcs, expert_line_error, expert_noise }

hostlink.prefs.tcp_port = Pref.uint("TCP port", 4001, "The raw TCP port of the serial-device server in front of the PLC")

-- The C-mode headers and their names, as the library's command table (src/OmronHostLink/Protocol/CMode) names them;
-- a test checks the two agree. Keys with four characters are a header and its sub-header.
local commands = {
    RR = "CIO AREA READ",
    RL = "LR AREA READ",
    RH = "HR AREA READ",
    RC = "TIMER/COUNTER PV READ",
    RG = "TIMER/COUNTER STATUS READ",
    RD = "DM AREA READ",
    RJ = "AR AREA READ",
    RE = "EM AREA READ",
    WR = "CIO AREA WRITE",
    WL = "LR AREA WRITE",
    WH = "HR AREA WRITE",
    WC = "TIMER/COUNTER PV WRITE",
    WD = "DM AREA WRITE",
    WJ = "AR AREA WRITE",
    WE = "EM AREA WRITE",
    ["R#"] = "SV READ 1",
    ["R$"] = "SV READ 2",
    ["R%"] = "SV READ 3",
    ["W#"] = "SV CHANGE 1",
    ["W$"] = "SV CHANGE 2",
    ["W%"] = "SV CHANGE 3",
    MS = "STATUS READ",
    SC = "STATUS CHANGE",
    MF = "ERROR READ",
    KS = "FORCED SET",
    KR = "FORCED RESET",
    FK = "MULTIPLE FORCED SET/RESET",
    KC = "FORCED SET/RESET CANCEL",
    MM = "PLC MODEL READ",
    TS = "TEST",
    RP = "PROGRAM READ",
    WP = "PROGRAM WRITE",
    MI = "I/O TABLE GENERATE",
    QQMR = "REGISTER I/O MEMORY (QQMR)",
    QQIR = "READ I/O MEMORY (QQIR)",
    XZ = "ABORT",
    ["**"] = "INITIALIZE",
    IC = "UNDEFINED COMMAND (response)",
    EX = "TXD (PLC to host)",
    FA = "FINS COMMAND OVER HOST LINK",
}

-- The C-mode end codes, as the library's EndCode type describes them (a test checks the two agree).
local end_codes = {
    ["00"] = "Normal completion",
    ["01"] = "Not executable in RUN mode",
    ["02"] = "Not executable in MONITOR mode",
    ["03"] = "UM write-protected",
    ["04"] = "Address over: the program address is beyond the end of the program",
    ["0B"] = "Not executable in PROGRAM mode",
    ["0C"] = "Not executable in DEBUG mode",
    ["10"] = "Parity error",
    ["11"] = "Framing error",
    ["12"] = "Overrun",
    ["13"] = "FCS error: the PLC received a frame whose check characters did not match",
    ["14"] = "Format error: wrong command length or format, or a command that may not be divided was divided",
    ["15"] = "Entry number data error: an address or count is out of range or not in BCD/hex",
    ["16"] = "Command not supported, or the SV operand was not found",
    ["18"] = "Frame length error: the frame is longer than the PLC accepts",
    ["19"] = "Not executable: nothing registered, SV over 9999, or no access right",
    ["20"] = "The I/O table could not be created",
    ["21"] = "Not executable because of a CPU Unit error",
    ["22"] = "Memory does not exist",
    ["23"] = "User memory is protected",
    ["A0"] = "Aborted: parity error in transmitted data",
    ["A1"] = "Aborted: framing error in transmitted data",
    ["A2"] = "Aborted: overrun in transmitted data",
    ["A3"] = "Aborted: FCS error in the second or a later frame",
    ["A4"] = "Aborted: format error in the second or a later frame",
    ["A5"] = "Aborted: entry number data error in the second or a later frame",
    ["A8"] = "Aborted: frame length error in the second or a later frame",
    ["B0"] = "Program area error",
}

-- The FINS commands the library models (src/OmronHostLink/Protocol/Fins; a test checks the two agree).
local fins_commands = {
    ["0101"] = "MEMORY AREA READ",
    ["0102"] = "MEMORY AREA WRITE",
    ["0103"] = "MEMORY AREA FILL",
    ["0104"] = "MULTIPLE MEMORY AREA READ",
    ["0105"] = "MEMORY AREA TRANSFER",
    ["0401"] = "RUN",
    ["0402"] = "STOP",
    ["0501"] = "CPU UNIT DATA READ",
    ["0601"] = "CPU UNIT STATUS READ",
    ["0620"] = "CYCLE TIME READ",
    ["0701"] = "CLOCK READ",
    ["0702"] = "CLOCK WRITE",
    ["2101"] = "ERROR CLEAR",
    ["2102"] = "ERROR LOG READ",
    ["2301"] = "FORCED SET/RESET",
    ["2302"] = "FORCED SET/RESET CANCEL",
}

-- FINS response codes by main code (W342 section 5).
local fins_main_codes = {
    ["00"] = "Normal completion",
    ["01"] = "Local node error",
    ["02"] = "Destination node error",
    ["03"] = "Communications controller error",
    ["04"] = "Not executable (undefined or unsupported command)",
    ["05"] = "Routing table error",
    ["10"] = "Command format error",
    ["11"] = "Parameter error",
    ["20"] = "Read not possible",
    ["21"] = "Write not possible",
    ["22"] = "Not executable in current mode",
    ["23"] = "No such device",
    ["24"] = "Cannot start/stop",
    ["25"] = "Unit error",
    ["26"] = "Command error",
    ["30"] = "Access right error",
    ["40"] = "Abort",
}

-- Bitwise exclusive or of two bytes, without relying on a Lua version's bit library.
local function xor8(a, b)
    local result, bit = 0, 1
    for _ = 1, 8 do
        if (a % 2) ~= (b % 2) then result = result + bit end
        a, b, bit = math.floor(a / 2), math.floor(b / 2), bit * 2
    end
    return result
end

local function is_hex(s) return s:match("^[0-9A-F]+$") ~= nil end

-- What came before each frame, per capture: the first frame of the message a later frame belongs to.
local last_first = {}   -- direction -> { number, unit, header, answer }
local remembered = {}   -- frame number (and index within it) -> context of a later frame

local function reset_state()
    last_first = {}
    remembered = {}
end

-- The FINS header after the ICF at `at` (the ICF's bit 7 marks the network form, with RSV, GCT, DNA, DA1, DA2, SNA,
-- SA1 and SA2; else DA2 and SA2 only), the SID and the command code; returns where the parameters (or, in an answer,
-- the response code) start.
local function fins_header(tree, text, at)
    local icf = text:sub(at, at + 1)
    tree:add(pf.fins_icf, icf)
    at = at + 2
    if tonumber(icf, 16) and tonumber(icf, 16) >= 0x80 then
        at = at + 8 * 2
    else
        tree:add(pf.fins_da2, text:sub(at, at + 1))
        tree:add(pf.fins_sa2, text:sub(at + 2, at + 3))
        at = at + 4
    end
    tree:add(pf.fins_sid, text:sub(at, at + 1))
    local command = text:sub(at + 2, at + 5)
    tree:add(pf.fins_command, command)
    if fins_commands[command] then tree:add(pf.fins_command_name, fins_commands[command]) end
    return at + 6
end

-- The FINS part of an FA frame (text: the characters after "FA" and before the FCS): a command's response wait and
-- parameters, an answer's response code with its flags and data. Returns an answer's response code.
local function describe_fins(tree, text, answer)
    if not answer then
        tree:add(pf.fins_wait, text:sub(1, 1))
        local at = fins_header(tree, text, 2)
        if #text >= at then tree:add(pf.fins_data, text:sub(at)) end
        return nil
    end
    if text:sub(1, 2) ~= "00" or #text < 4 then return nil end
    local at = fins_header(tree, text, 3)
    local response = text:sub(at, at + 3)
    if #response ~= 4 or not is_hex(response) then return nil end
    local value = tonumber(response, 16)
    local main = string.format("%02X", math.floor(value / 256) % 128)
    local flags = {}
    if value >= 0x8000 then flags[#flags + 1] = "network relay error" end
    if math.floor(value / 128) % 2 == 1 then flags[#flags + 1] = "fatal CPU error" end
    if math.floor(value / 64) % 2 == 1 then flags[#flags + 1] = "non-fatal CPU error" end
    tree:add(pf.fins_response_code, response)
    local meaning = fins_main_codes[main] or "Unknown main code"
    if #flags > 0 then meaning = meaning .. " (" .. table.concat(flags, ", ") .. ")" end
    tree:add(pf.fins_response_meaning, meaning)
    if #text >= at + 4 then tree:add(pf.fins_data, text:sub(at + 4)) end
    return response
end

-- Decodes one frame (bytes up to and including CR) in tvb range `range`; returns a short summary for the Info column.
local function dissect_frame(range, pinfo, tree, direction, key, show_direction)
    local bytes = range:bytes()
    local n = bytes:len()
    local s = range:string()
    local subtree = tree:add(hostlink, range)
    if show_direction then subtree:add(pf.direction, direction):set_generated() end

    if n == 1 and bytes:get_index(0) == 13 then
        subtree:add(pf.kind, "delimiter")
        subtree:append_text(": CR (next frame, please)")
        return "CR (next frame)"
    end

    if s:sub(1, 3) == "@**" then
        subtree:add(pf.kind, "initialize")
        subtree:add(pf.header, "**")
        subtree:add(pf.name, commands["**"])
        return "@** INITIALIZE"
    end

    local ends_cr = bytes:get_index(n - 1) == 13
    local final = ends_cr and n >= 2 and bytes:get_index(n - 2) == 42
    local fcs_end = n - (final and 2 or 1)
    local fcs_at = fcs_end - 2
    if not ends_cr or fcs_at < 0 then
        subtree:add(pf.kind, "noise")
        subtree:add_proto_expert_info(expert_noise, "Not a frame: " .. (ends_cr and "too short to hold an FCS" or "no CR at the end"))
        return "bytes that do not frame"
    end

    local first = s:sub(1, 1) == "@"
    local check = 0
    for i = 0, fcs_at - 1 do check = xor8(check, bytes:get_index(i)) end
    local expected = string.format("%02X", check)
    local found = s:sub(fcs_at + 1, fcs_at + 2)
    local good = found == expected

    local unit, header, answer, text, sub
    local summary
    if first then
        unit = tonumber(s:sub(2, 3))
        header = s:sub(4, 5)
        text = s:sub(6, fcs_at)
        answer = direction == 2
        subtree:add(pf.kind, answer and "answer" or "command")
        if unit ~= nil then subtree:add(pf.unit, range(1, 2), unit) end
        subtree:add(pf.header, range(3, 2), header)
        sub = (header == "QQ") and text:sub(1, 2) or ""
        local name = commands[header .. sub] or commands[header]
        if name then subtree:add(pf.name, name) end
        if not pinfo.visited then
            last_first[direction or 0] = { number = pinfo.number, unit = unit, header = header, answer = answer }
        end
        summary = string.format("%s %s%s", unit and string.format("%02d", unit) or "??", header, sub)
    else
        local context = remembered[key]
        if context == nil and not pinfo.visited then
            context = last_first[direction or 0]
            remembered[key] = context
        end
        subtree:add(pf.kind, "continuation")
        text = s:sub(1, fcs_at)
        if context then
            subtree:add(pf.first_frame, context.number)
            if context.unit then subtree:add(pf.unit, context.unit):set_generated() end
            subtree:add(pf.header, context.header):set_generated()
            answer = context.answer
            header = context.header
            summary = string.format("%s %s (continued)", context.unit and string.format("%02d", context.unit) or "??", context.header)
        else
            summary = "later frame"
        end
    end

    -- The end code of an answer: after the header (and sub-header); TS answers with its own text, IC and EX have none.
    if first and answer and header ~= "IC" and header ~= "EX" and header ~= "TS" and #text >= #sub + 2 then
        local code = text:sub(#sub + 1, #sub + 2)
        subtree:add(pf.end_code, code)
        subtree:add(pf.end_code_meaning, end_codes[code] or "not an end code the manuals define")
        summary = summary .. " end " .. code
        if header == "FA" then
            local response = describe_fins(subtree, text, true)
            if response then summary = summary .. "/" .. response end
        end
    elseif first and answer and header == "TS" and #text == 2 and is_hex(text) then
        subtree:add(pf.end_code, text)
        subtree:add(pf.end_code_meaning, end_codes[text] or "not an end code the manuals define")
        summary = summary .. " end " .. text
    elseif first and header == "FA" and not answer then
        describe_fins(subtree, text, false)
    end

    subtree:add(pf.text, text)
    subtree:add(pf.fcs, range(fcs_at, 2), found)
    subtree:add(pf.fcs_expected, expected):set_generated()
    local status = subtree:add(pf.fcs_status, good and "good" or "bad")
    status:set_generated()
    if not good then
        status:add_proto_expert_info(expert_bad_fcs, string.format("Bad FCS: the frame carries %s, its characters give %s", found, expected))
        summary = summary .. " [BAD FCS]"
    end
    subtree:add(pf.final, final)
    subtree:append_text(": " .. summary)
    return summary
end

function hostlink.init()
    reset_state()
end

-- Records of a hostlink capture (link type 147).
function hostlink.dissector(tvb, pinfo, tree)
    if tvb:len() < 12 or tvb(0, 2):string() ~= "HL" then return 0 end
    pinfo.cols.protocol = "HostLink"
    local direction = tvb(3, 1):uint()
    local flags = tvb(4, 1):uint()
    local record = tree:add(hostlink, tvb(0, 12), "Host Link capture record")
    record:add(pf.direction, tvb(3, 1))
    record:add(pf.flags, tvb(4, 1))
    record:add(pf.duration, tvb(8, 4))
    if direction == 1 then
        pinfo.cols.src, pinfo.cols.dst = "host", "PLC"
    elseif direction == 2 then
        pinfo.cols.src, pinfo.cols.dst = "PLC", "host"
    end
    if tvb:len() == 12 then return 12 end
    local summary
    if flags % 4 >= 2 then
        local item = tree:add(hostlink, tvb(12), "Bytes that do not frame")
        item:add(pf.kind, "noise")
        item:add_proto_expert_info(expert_noise)
        summary = string.format("%d bytes that do not frame", tvb:len() - 12)
    else
        summary = dissect_frame(tvb(12), pinfo, tree, direction, pinfo.number, false)
    end
    if flags % 2 == 1 then tree:add_proto_expert_info(expert_line_error) end
    pinfo.cols.info = (directions[direction] or "?") .. ": " .. summary
    return tvb:len()
end

-- A serial-device server's raw TCP stream: frames cut at each CR, reassembled across segments; the server is the PLC.
local function dissect_tcp(tvb, pinfo, tree)
    local length = tvb:len()
    local offset = 0
    local summaries = {}
    local direction = (pinfo.src_port == hostlink.prefs.tcp_port) and 2 or 1
    while offset < length do
        local cr
        for i = offset, length - 1 do
            if tvb(i, 1):uint() == 13 then cr = i break end
        end
        if cr == nil then
            pinfo.desegment_offset = offset
            pinfo.desegment_len = DESEGMENT_ONE_MORE_SEGMENT
            break
        end
        summaries[#summaries + 1] = dissect_frame(tvb(offset, cr - offset + 1), pinfo, tree, direction, pinfo.number * 1000 + #summaries, true)
        offset = cr + 1
    end
    if #summaries > 0 then
        pinfo.cols.protocol = "HostLink"
        pinfo.cols.info = (directions[direction] or "?") .. ": " .. table.concat(summaries, "; ")
    end
    return length
end

local tcp_dissector = Proto("hostlink_tcp", "Omron Host Link over TCP")
tcp_dissector.dissector = dissect_tcp

DissectorTable.get("wtap_encap"):add(wtap_encaps.USER0, hostlink)
local registered_port = hostlink.prefs.tcp_port
DissectorTable.get("tcp.port"):add(registered_port, tcp_dissector)

function hostlink.prefs_changed()
    if registered_port ~= hostlink.prefs.tcp_port then
        DissectorTable.get("tcp.port"):remove(registered_port, tcp_dissector)
        registered_port = hostlink.prefs.tcp_port
        DissectorTable.get("tcp.port"):add(registered_port, tcp_dissector)
    end
end
