/*  Tests of the wire layer (prolog/oro/server/oro_protocol.pl): value encoding,
    writers, and request framing over real sockets on 127.0.0.1.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_protocol_framing.pl
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(socket)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(oro/server/oro_protocol)).


                 /*******************************
                 *          ECHO SERVER         *
                 *******************************/

%   A tiny server on an ephemeral 127.0.0.1 port.  Each connection has
%   its own thread that reads requests with oro_reader/3, oro_read_request/3 and
%   answers
%
%     - request(M, Ps)       ok  ["M","P1",...]
%     - request("close", _)  Closing now!, then the connection ends
%     - help                 ok  "help"
%     - bad(encoding)        error EncodingError
%     - bad(too_large(L))    error RequestTooLarge, then drains the
%                            input and ends (as a real server closes)
%
%   When a connection thread ends it sends done(Status) to the server's
%   queue: end_of_file, closed, too_large or exception(E).

:- dynamic echo_server/3.               % Name, Port, server(...)

start_echo_server(Name, Options) :-
    tcp_socket(Socket),
    tcp_setopt(Socket, reuseaddr),
    tcp_bind(Socket, '127.0.0.1':Port),
    tcp_listen(Socket, 16),
    message_queue_create(Done),
    thread_create(accept_loop(Socket, Options, Done), Acceptor, []),
    assertz(echo_server(Name, Port, server(Socket, Acceptor, Done))).

stop_echo_server(Name) :-
    retract(echo_server(Name, _, server(Socket, Acceptor, Done))),
    thread_signal(Acceptor, throw(stop_echo_server)),
    thread_join(Acceptor, _),
    tcp_close_socket(Socket),
    message_queue_destroy(Done).

accept_loop(Socket, Options, Done) :-
    catch(accept_connections(Socket, Options, Done), stop_echo_server, true).

accept_connections(Socket, Options, Done) :-
    tcp_accept(Socket, Client, _Peer),
    thread_create(serve(Client, Options, Done), _, [detached(true)]),
    accept_connections(Socket, Options, Done).

serve(Client, Options, Done) :-
    tcp_open_socket(Client, Pair),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(In, newline(posix)),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)),
    catch(( oro_reader(In, Reader, Options),
            serve_requests(Reader, Out, Status)
          ), E,
          Status = exception(E)),
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true),
    thread_send_message(Done, done(Status)).

serve_requests(Reader0, Out, Status) :-
    oro_read_request(Reader0, Request, Reader),
    Reader = oro_reader(In, _, _, _),
    (   Request == end_of_file
    ->  Status = end_of_file
    ;   Request = request(Method, _),
        string_lower(Method, "close")
    ->  oro_write_closing(Out),
        Status = closed
    ;   Request = bad(too_large(Limit))
    ->  format(string(Message), "Request larger than ~D bytes.", [Limit]),
        oro_write_error(Out, 'RequestTooLarge', Message),
        oro_drain_input(In, 100000000, 10),
        Status = too_large
    ;   answer(Request, Out),
        serve_requests(Reader, Out, Status)
    ).

answer(request(Method, Params), Out) :-
    maplist(string_value, [Method|Params], Values),
    oro_write_ok(Out, list(Values)).
answer(help, Out) :-
    oro_write_ok(Out, string("help")).
answer(bad(encoding), Out) :-
    oro_write_error(Out, 'EncodingError', "The request is not valid UTF-8.").

string_value(Text, string(Text)).

%   drain(+In): read and drop the rest of the input until the peer
%   closes (bounded by a stream timeout).

server_port(Name, Port) :-
    echo_server(Name, Port, _).

%   with_connection(+Server, -Conn, :Goal, -Status)
%
%   Run Goal once with a connection; afterwards, whatever Goal did,
%   disconnect and wait (10 s at most) for the server's connection
%   thread to end with Status.  Every connection's done/1 message is
%   consumed here, so the next test reads its own.

:- meta_predicate with_connection(+, -, 0, -).

with_connection(Server, Conn, Goal, Status) :-
    echo_server(Server, Port, server(_, _, Done)),
    oro_connect(Port, Conn),
    (   catch(Goal, Error, true)
    ->  Result = true
    ;   Result = false
    ),
    oro_disconnect(Conn),
    (   thread_get_message(Done, done(Status0), [timeout(10)])
    ->  Status = Status0
    ;   Status = no_status
    ),
    (   nonvar(Error)
    ->  throw(Error)
    ;   Result == true
    ).

%   echo(+Method, +Params, -Reply): the echo server's reply.

echo(Method, Params, ok(Line)) :-
    maplist(string_value, [Method|Params], Values),
    oro_encode_value(list(Values), Line).

string_of(Length, Code, String) :-
    format(string(String), "~*c", [Length, Code]).


                 /*******************************
                 *        VALUE ENCODING        *
                 *******************************/

:- begin_tests(oro_encode_value).

test(void, S == "") :-
    oro_encode_value(void, S).
test(string, S == "\"toto\"") :-
    oro_encode_value(string("toto"), S).
test(string_atom, S == "\"toto\"") :-
    oro_encode_value(string(toto), S).
test(string_quotes_single_quoted, S == "'toto et \"tata\"'") :-
    oro_encode_value(string("toto et \"tata\""), S).
test(string_both_quotes_escaped, S == "\"it's \\\"x\\\"\"") :-
    oro_encode_value(string("it's \"x\""), S).
test(string_backslash_verbatim, S == "\"a\\b\"") :-
    oro_encode_value(string("a\\b"), S).
test(string_backslash_escaped_with_newline, S == "\"a\\\\b\\nc\"") :-
    oro_encode_value(string("a\\b\nc"), S).
test(string_newlines_escaped, S == "\"a\\nb\\rc\"") :-
    oro_encode_value(string("a\nb\rc"), S).
test(string_nul_escaped, S == "\"a\\u0000b\"") :-
    oro_encode_value(string("a\u0000b"), S).
test(string_controls_raw, S == "\"a\tb\u001fc\"") :-
    oro_encode_value(string("a\tb\u001fc"), S).
test(string_unicode, S == "\"日本 😀\"") :-
    oro_encode_value(string("日本 😀"), S).
test(multiline_string, S == "\"a\nb \\\"c\\\"\"") :-
    oro_encode_value(multiline_string("a\nb \"c\""), S).
test(float, S == "3.1415") :-
    oro_encode_value(float(3.1415), S).
test(float_of_integer, S == "3.0") :-
    oro_encode_value(float(3), S).
test(float_special, S == "[Infinity,-Infinity,NaN]") :-
    Inf is inf,
    MinusInf is -inf,
    NaN is nan,
    oro_encode_value(list([float(Inf), float(MinusInf), float(NaN)]), S).
test(int, S == "42") :-
    oro_encode_value(int(42), S).
test(true, S == "true") :-
    oro_encode_value(bool(true), S).
test(false, S == "false") :-
    oro_encode_value(bool(false), S).
test(null, S == "null") :-
    oro_encode_value(null, S).
test(raw, S == "0f1e2d3c-aaaa-bbbb-cccc-0123456789ab") :-
    oro_encode_value(raw('0f1e2d3c-aaaa-bbbb-cccc-0123456789ab'), S).
test(raw_json, S == "{\"name\": \"x\"}") :-
    oro_encode_value(raw("{\"name\": \"x\"}"), S).
test(list, S == "[\"toto\",\"tata\"]") :-
    oro_encode_value(list(["toto", "tata"]), S).
test(list_of_value_terms, S == "[\"toto\",\"tata\"]") :-
    oro_encode_value(list([string(toto), string("tata")]), S).
test(empty_list, S == "[]") :-
    oro_encode_value(list([]), S).
test(map, S == "{1:\"toto\",2:\"tata\"}") :-
    oro_encode_value(map([int(1)-"toto", 2-string(tata)]), S).
test(map_strings, S == "{\"k\":\"v\"}") :-
    oro_encode_value(map([k-v]), S).
test(empty_map, S == "{}") :-
    oro_encode_value(map([]), S).
test(nested_lists, S == "[[\"toto\",\"tata\"],[\"tutu\"]]") :-
    oro_encode_value(list([list([toto, tata]), list([tutu])]), S).
test(mixed_elements, S == "[null,1,2.5,\"true\",false,\"a\\\"b\"]") :-
    oro_encode_value(list([null, 1, 2.5, true, bool(false), "a\"b"]), S).
test(lookup_pairs, S == "[[\"baboon\",\"INSTANCE\"]]") :-
    oro_encode_value(list([list([baboon, "INSTANCE"])]), S).
test(big_string, Len == 3000002) :-
    string_of(3000000, 0'x, X),
    oro_encode_value(string(X), S),
    string_length(S, Len).
test(not_a_value, error(type_error(oro_value, foo))) :-
    oro_encode_value(foo, _).
test(bad_element, error(type_error(oro_value, list([f(x)])))) :-
    oro_encode_value(list([f(x)]), _).
test(bad_bool, error(type_error(oro_value, bool(maybe)))) :-
    oro_encode_value(bool(maybe), _).
test(unbound, error(instantiation_error)) :-
    oro_encode_value(_, _).

:- end_tests(oro_encode_value).


                 /*******************************
                 *            WRITERS           *
                 *******************************/

:- begin_tests(oro_writers).

test(ok, S == "ok\n[\"a\",\"b\"]\n#end#\n") :-
    with_output_to(string(S), oro_write_ok(current_output, list([a, b]))).
test(ok_void, S == "ok\n\n#end#\n") :-
    with_output_to(string(S), oro_write_ok(current_output, void)).
test(error, S == "error\nNotImplementedException\nMethod \"foo\" not implemented.\n#end#\n") :-
    with_output_to(string(S),
                   oro_write_error(current_output, 'NotImplementedException',
                                   "Method \"foo\" not implemented.")).
test(error_one_line, S == "error\nE\na b c d \n#end#\n") :-
    with_output_to(string(S),
                   oro_write_error(current_output, "E", "a\nb\r\nc\rd\n")).
test(error_empty_message, S == "error\nE\n\n#end#\n") :-
    with_output_to(string(S), oro_write_error(current_output, 'E', '')).
test(event_fact_checking, S == "event\n1b4e28ba-2fa1-11d2-883f-0016d3cca427\n\n#end#\n") :-
    with_output_to(string(S),
                   oro_write_event(current_output,
                                   '1b4e28ba-2fa1-11d2-883f-0016d3cca427', void)).
test(event_instances, S == "event\nid\n[\"fork1\"]\n#end#\n") :-
    with_output_to(string(S), oro_write_event(current_output, "id", list([fork1]))).
test(closing, S == "Closing now!\n") :-
    with_output_to(string(S), oro_write_closing(current_output)).
test(bad_value, error(type_error(oro_value, nope))) :-
    with_output_to(string(_), oro_write_ok(current_output, nope)).
test(not_a_stream, error(type_error(stream, nope))) :-
    oro_write_closing(nope).

:- end_tests(oro_writers).


                 /*******************************
                 *     READER ON MEMORY DATA    *
                 *******************************/

%   requests(+Text, +Options, -Requests): all requests of Text, read
%   from a temporary file (bytes exactly as given).

requests(Data, Options, Requests) :-
    (   Data = bytes(Bytes)
    ->  true
    ;   string_bytes(Data, Bytes, utf8)
    ),
    tmp_file_stream(octet, File, Tmp),
    forall(member(Byte, Bytes), put_byte(Tmp, Byte)),
    close(Tmp),
    setup_call_cleanup(
        open(File, read, In, [encoding(utf8), newline(posix)]),
        ( oro_reader(In, Reader, Options),
          read_all(Reader, 100, Requests)
        ),
        ( close(In), delete_file(File) )).

read_all(Reader0, Max, Requests) :-
    oro_read_request(Reader0, Request, Reader),
    (   Request == end_of_file
    ->  Requests = []
    ;   Max =:= 0
    ->  Requests = [too_many]
    ;   Requests = [Request|Rest],
        Max1 is Max - 1,
        read_all(Reader, Max1, Rest)
    ).

:- begin_tests(oro_read_request).

test(parser_vector,
     Rs == [ help,
             request("addForAgent", ["TOTO", "[\"TATA likes TOTO\"]"]),
             request("test2", []),
             help,
             request("test3", ["param1"])
           ]) :-
    requests("help\naddForAgent\nTOTO\n[\"TATA likes TOTO\"]\n#end#\ntest2\n\c
              #end#\nhelp\ntest3\nparam1\n#end#\n", [], Rs).
test(empty_input, Rs == []) :-
    requests("", [], Rs).
test(partial_request_at_eof, Rs == [request("a", [])]) :-
    requests("a\n#end#\nb\nc", [], Rs).
test(terminator_newline_is_optional, Rs == [request("a", []), request("b", ["x"])]) :-
    requests("a\n#end#b\nx#end#", [], Rs).
test(one_newline_belongs_to_terminator, Rs == [request("a", []), request("", [])]) :-
    requests("a\n#end#\n#end#\n", [], Rs).
test(crlf_after_terminator, Rs == [request("a", []), request("", [])]) :-
    requests("a\r\n#end#\r\n#end#\r\n", [], Rs).
test(empty_lines_only, Rs == [request("b", [])]) :-
    requests("\n\n#end#\n\r\n#end#b\n#end#\n", [], Rs).
test(embedded_and_trailing_empty_lines, Rs == [request("find", ["x", "", "[..]"])]) :-
    requests("find\nx\n\n[..]\n\n\n#end#\n", [], Rs).
test(help_end_swallowed, Rs == [help, request("a", [])]) :-
    requests("help\n#end#\na\n#end#\n", [], Rs).
test(help_blank_lines_then_end, Rs == [help, request("a", [])]) :-
    requests("help\r\n\r\n#end#\r\na\r\n#end#\r\n", [], Rs).
test(help_on_the_terminator_line, Rs == [help, request("", [])]) :-
    requests("help#end#\n#end#\n", [], Rs).
test(help_variants, Rs == [help, help, request("helpers", []), request(" help", [])]) :-
    requests("HELP\nHeLp \t\nhelpers\n#end#\n help\n#end#\n", [], Rs).
test(hash_characters, Rs == [request("a#b", ["#en", "#end", "##"])]) :-
    requests("a#b\n#en\n#end\n##\n#end#", [], Rs).
test(nul, Rs == [request("a\u0000b", ["\u0000"])]) :-
    requests("a\u0000b\n\u0000\n#end#\n", [], Rs).
test(pending_after_first_of_two, Pending == true) :-
    setup_call_cleanup(
        open_string("a\n#end#\nb\nx\n#end#\n", In),
        ( oro_reader(In, R0, []),
          oro_read_request(R0, request("a", []), R1),
          pending(R1, Pending)
        ),
        close(In)).
test(pending_on_socket, Pending == [false, true]) :-
    tcp_socket(Listen),
    tcp_bind(Listen, '127.0.0.1':Port),
    tcp_listen(Listen, 1),
    tcp_open_socket(Listen, Server),
    tcp_connect('127.0.0.1':Port, Client, []),
    setup_call_cleanup(
        tcp_accept(Listen, Socket, _),
        setup_call_cleanup(
            tcp_open_socket(Socket, Pair),
            ( stream_pair(Pair, In, _),
              oro_reader(In, R0, []),
              format(Client, "a\n#end#\n", []),
              flush_output(Client),
              oro_read_request(R0, request("a", []), R1),
              pending(R1, P1),
              format(Client, "b\n#end#\n", []),
              flush_output(Client),
              wait_for_input([In], _, 10),
              pending(R1, P2),
              Pending = [P1, P2]
            ),
            close(Pair, [force(true)])),
        ( close(Client, [force(true)]),
          close(Server, [force(true)])
        )).
test(invalid_utf8, Rs == [bad(encoding), request("ok", [])]) :-
    append([`a\n`, [0xFF], `\n#end#\nok\n#end#\n`], Bytes),
    requests(bytes(Bytes), [], Rs).
test(overlong_nul, Rs == [bad(encoding), request("ok", [])]) :-
    append([`a\n`, [0xC0, 0x80], `#end#ok#end#`], Bytes),
    requests(bytes(Bytes), [], Rs).
test(surrogate, Rs == [bad(encoding), request("ok", [])]) :-
    append([[0xED, 0xA0, 0x80], `\n#end#ok#end#`], Bytes),
    requests(bytes(Bytes), [], Rs).
test(above_max_code_point, Rs == [bad(encoding), request("ok", [])]) :-
    append([[0xF4, 0x90, 0x80, 0x80], `\n#end#ok#end#`], Bytes),
    requests(bytes(Bytes), [], Rs).
test(truncated_sequence, Rs == [bad(encoding), request("ok", [])]) :-
    append([`x`, [0xE6, 0x97], `\n#end#ok#end#`], Bytes),
    requests(bytes(Bytes), [], Rs).
test(valid_edge_code_points, Rs == [request("\u00e9\uD7FF\uE000\U0010FFFF", [])]) :-
    requests(bytes([0xC3, 0xA9, 0xED, 0x9F, 0xBF, 0xEE, 0x80, 0x80,
                    0xF4, 0x8F, 0xBF, 0xBF, 0'#, 0'e, 0'n, 0'd, 0'#]), [], Rs).
test(too_large, true(Rs = [bad(too_large(10))|_])) :-
    requests("abcdefghij\nklmnop\n#end#", [max_request_size(10)], Rs).
test(string_stream, Rs == [request("é", ["b"]), help]) :-
    setup_call_cleanup(
        open_string("é\nb\n#end#help\n#end#", In),
        ( oro_reader(In, Reader, []),
          read_all(Reader, 10, Rs)
        ),
        close(In)).
test(bad_option, error(type_error(positive_integer, 0))) :-
    setup_call_cleanup(
        open_string("a#end#", In),
        oro_reader(In, _, [max_request_size(0)]),
        close(In)).
test(not_a_stream, error(existence_error(stream, nope))) :-
    oro_reader(nope, _, []).
test(unbound_stream, error(instantiation_error)) :-
    oro_reader(_, _, []).

:- end_tests(oro_read_request).

pending(Reader, Pending) :-
    (   oro_reader_pending(Reader)
    ->  Pending = true
    ;   Pending = false
    ).


                 /*******************************
                 *        FRAMING (SOCKETS)     *
                 *******************************/

:- begin_tests(protocol_framing,
               [ setup(start_echo_server(framing, [])),
                 cleanup(stop_echo_server(framing))
               ]).

test(parser_vector,
     Replies-Status == [H, AddForAgent, Test2, H, Test3]-end_of_file) :-
    H = ok("\"help\""),
    echo("addForAgent", ["TOTO", "[\"TATA likes TOTO\"]"], AddForAgent),
    echo("test2", [], Test2),
    echo("test3", ["param1"], Test3),
    with_connection(framing, C,
                    ( oro_send_raw(C, "help\naddForAgent\nTOTO\n\c
                                       [\"TATA likes TOTO\"]\n#end#\ntest2\n"),
                      test_receive_n(C, 2, R1),
                      oro_send_raw(C, "#end#\nhelp\ntest3\nparam1\n#end"),
                      test_receive_n(C, 2, R2),
                      oro_send_raw(C, "#\n"),
                      test_receive_n(C, 1, R3),
                      append([R1, R2, R3], Replies)
                    ),
                    Status).
test(incomplete_terminator_not_answered, Reply == timeout) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "test3\nparam1\n#end"),
                      oro_receive(C, Reply, 0.3)
                    ),
                    _).
test(hello, Reply == ok("[\"hello\"]")) :-
    with_connection(framing, C, oro_call(C, hello, [], Reply), _).
test(crlf, Replies == [A, P]) :-
    echo("add", ["[a b c]"], A),
    echo("ping", [], P),
    with_connection(framing, C,
                    ( oro_send_raw(C, "add\r\n[a b c]\r\n#end#\r\nping\r\n#end#\r\n"),
                      test_receive_n(C, 2, Replies)
                    ),
                    _).
test(lone_cr, Replies == [A, P]) :-
    echo("add", ["[a b c]"], A),
    echo("ping", [], P),
    with_connection(framing, C,
                    ( oro_send_raw(C, "add\r[a b c]\r#end#\rping\r#end#\r"),
                      test_receive_n(C, 2, Replies)
                    ),
                    _).
test(end_on_same_line, Replies == [A]) :-
    echo("add", ["[a b c]"], A),
    with_connection(framing, C,
                    ( oro_send_raw(C, "add\n[a b c]#end#"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(pipelined, Replies == [A, B, X]) :-
    echo("a", [], A),
    echo("b", ["x"], B),
    echo("c", [], X),
    with_connection(framing, C,
                    ( oro_send_raw(C, "a\n#end#\nb\nx\n#end#c\n#end#\n"),
                      test_receive_n(C, 3, Replies)
                    ),
                    _).
test(many_pipelined, Replies == Expected) :-
    numlist(1, 200, Ns),
    maplist([N, Req]>>format(string(Req), "m~w\np~w\n#end#\n", [N, N]), Ns, Reqs),
    atomics_to_string(Reqs, Text),
    maplist([N, E]>>( format(string(M), "m~w", [N]),
                      format(string(Param), "p~w", [N]),
                      echo(M, [Param], E)
                    ), Ns, Expected),
    with_connection(framing, C,
                    ( oro_send_raw(C, Text),
                      test_receive_n(C, 200, Replies)
                    ),
                    _).
test(leading_blank_lines, Replies == [F]) :-
    echo("foo", ["bar"], F),
    with_connection(framing, C,
                    ( oro_send_raw(C, "\n\n\r\nfoo\nbar\n#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(bare_end, Replies == [ok("[\"\"]")]) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(bare_end_after_request, Replies == [F, ok("[\"\"]")]) :-
    echo("foo", [], F),
    with_connection(framing, C,
                    ( oro_send_raw(C, "foo\n#end#\n#end#\n"),
                      test_receive_n(C, 2, Replies)
                    ),
                    _).
test(empty_lines_request_discarded, Replies == [P]) :-
    echo("ping", [], P),
    with_connection(framing, C,
                    ( oro_send_raw(C, "\n\n#end#\nping\n#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(embedded_empty_lines, Replies == [F]) :-
    echo("find", ["x", "", "[..]"], F),
    with_connection(framing, C,
                    ( oro_send_raw(C, "find\nx\n\n[..]\n\n#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(method_verbatim, Replies == [ok("[\"add \"]")]) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "add \n#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(help_end_swallowed, Replies == [ok("\"help\""), P]) :-
    echo("ping", [], P),
    with_connection(framing, C,
                    ( oro_send_raw(C, "help\n#end#\nping\n#end#\n"),
                      test_receive_n(C, 2, Replies)
                    ),
                    _).
test(help_answered_before_end, Reply == ok("\"help\"")) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "HeLp \r\n"),
                      oro_receive(C, Reply)
                    ),
                    _).
test(help_end_sent_later, Replies == [ok("\"help\""), P]) :-
    echo("ping", [], P),
    with_connection(framing, C,
                    ( oro_send_raw(C, "help\n"),
                      oro_receive(C, R1),
                      oro_send_raw(C, "#end#\nping\n#end#\n"),
                      oro_receive(C, R2),
                      Replies = [R1, R2]
                    ),
                    _).
test(nul_bytes, Replies == [A]) :-
    echo("a\u0000b", ["\u0000"], A),
    with_connection(framing, C,
                    ( oro_send_raw(C, "a\u0000b\n\u0000\n#end#\n"),
                      test_receive_n(C, 1, Replies)
                    ),
                    _).
test(unicode, Replies == [A]) :-
    echo("añ", ["日本", "😀", "\"q\" \\"], A),
    with_connection(framing, C,
                    ( oro_call(C, "añ", ["日本", "😀", "\"q\" \\"], Reply),
                      Replies = [Reply]
                    ),
                    _).
test(invalid_utf8_then_valid,
     Replies == [error("EncodingError", "The request is not valid UTF-8."), P]) :-
    echo("ping", [], P),
    append([`add\n`, [0xFF, 0xFE], `\n#end#\nping\n#end#\n`], Bytes),
    with_connection(framing, C,
                    ( oro_send_raw(C, bytes(Bytes)),
                      test_receive_n(C, 2, Replies)
                    ),
                    _).
test(invalid_utf8_variants, Replies == [E, E, E, P]) :-
    E = error("EncodingError", "The request is not valid UTF-8."),
    echo("ping", [], P),
    append([ `a`, [0xC3], `#end#`,                  % truncated, #end# on the line
             [0xC0, 0x80], `\nx\n#end#\n`,          % overlong NUL
             `b\n`, [0xED, 0xA0, 0x80], `#end#`,    % surrogate
             `ping\n#end#\n`
           ], Bytes),
    with_connection(framing, C,
                    ( oro_send_raw(C, bytes(Bytes)),
                      test_receive_n(C, 4, Replies)
                    ),
                    _).
test(big_line, [Len-Status == 3000010-end_of_file]) :-
    string_of(3000000, 0'x, Big),
    with_connection(framing, C,
                    ( oro_call(C, big, [Big], ok(Line)),
                      string_length(Line, Len)
                    ),
                    Status).
test(big_unicode_line, [Reply == Expected]) :-
    length(Cs, 300000),
    maplist(=(0'é), Cs),
    string_codes(S0, Cs),
    string_concat(S0, "日本😀", Big),
    echo(big, [Big], Expected),
    with_connection(framing, C, oro_call(C, big, [Big], Reply), _).
test(disconnect_mid_request, Status == end_of_file) :-
    with_connection(framing, C, oro_send_raw(C, "add\n[a b"), Status).
test(disconnect_after_help, Status == end_of_file) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "help\n"),
                      oro_receive(C, ok(_))
                    ),
                    Status).
test(close, [Replies-Status == [closing, end_of_file]-closed]) :-
    with_connection(framing, C,
                    ( oro_send_raw(C, "close\n#end#\n"),
                      test_receive_n(C, 2, Replies)
                    ),
                    Status).

:- end_tests(protocol_framing).


:- begin_tests(protocol_limits,
               [ setup(start_echo_server(limits, [max_request_size(1048576)])),
                 cleanup(stop_echo_server(limits))
               ]).

test(under_limit, Len == 500011) :-
    string_of(500000, 0'y, Line),
    with_connection(limits, C,
                    ( oro_call(C, fits, [Line], ok(Reply)),
                      string_length(Reply, Len)
                    ),
                    _).
test(too_large,
     [ Reply-Status-After ==
       error("RequestTooLarge", "Request larger than 1,048,576 bytes.")-too_large-P
     ]) :-
    echo("ping", [], P),
    string_of(5000000, 0'x, Big),
    atomics_to_string(["big\n", Big, "\n#end#\nping\n#end#\n"], Data),
    with_connection(limits, C,
                    ( thread_create(catch(oro_send_raw(C, Data), _, true),
                                    Sender, []),
                      oro_receive(C, Reply),
                      thread_join(Sender, _)
                    ),
                    Status),
    with_connection(limits, C2, oro_call(C2, ping, [], After), _).
test(too_large_without_newline,
     true(Reply-Status = error("RequestTooLarge", _)-too_large)) :-
    string_of(2000000, 0'z, Big),
    with_connection(limits, C,
                    ( thread_create(catch(oro_send_raw(C, Big), _, true),
                                    Sender, []),
                      oro_receive(C, Reply),
                      thread_join(Sender, _)
                    ),
                    Status).

:- end_tests(protocol_limits).
