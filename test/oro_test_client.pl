:- module(oro_test_client,
          [ oro_connect/2,              % +Port, -Conn
            oro_connect/3,              % +Port, -Conn, +Options
            oro_disconnect/1,           % +Conn
            oro_send/3,                 % +Conn, +Method, +Params
            oro_send_raw/2,             % +Conn, +Data
            oro_receive/2,              % +Conn, -Message
            oro_receive/3,              % +Conn, -Message, +TimeoutSeconds
            oro_call/4,                 % +Conn, +Method, +Params, -Reply
            oro_call/5,                 % +Conn, +Method, +Params, -Reply, +TimeoutSeconds
            oro_next_event/2,           % +Conn, -Event
            oro_next_event/3,           % +Conn, -Event, +TimeoutSeconds
            oro_send_data/2,            % +Conn, +Parts
            oro_half_close/1,           % +Conn
            oro_drain/3                 % +Conn, -Messages, +TimeoutSeconds
          ]).
:- use_module(library(socket)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module(oro_client_parsers).

/** <module> A small ORO client for protocol tests

Connects to an ORO server on 127.0.0.1, sends requests (or raw bytes,
for framing tests) and reads the server's messages with bounded waits,
so a test never hangs: every receive has a timeout (10 seconds unless
given).

A connection is an opaque term oro_conn(In, Out, Events, Replies)
holding the socket streams (UTF-8) and two message queues: events that
arrived while oro_call/4 waited for its reply, and replies that arrived
while oro_next_event/2 waited for an event.

Messages are

  - ok(Value)              Value is the value line as a string (the
                           lines between `ok` and `#end#` joined with
                           `\n`, for the multi-line help text)
  - error(Name, Message)   strings
  - event(Id, Content)     strings
  - closing                the server's `Closing now!`
  - end_of_file            the server closed the connection
  - timeout                nothing complete arrived in time
  - unexpected(Line)       a line that starts no known message

Every value line received is checked against the rules by which liboro
and pyoro read it (oro_client_parsers.pl): a line either client would
fail on raises error(oro_client_read(Problem, Line), _).
*/

default_timeout(10).

%!  oro_connect(+Port, -Conn) is det.
%
%   Connect to the server on 127.0.0.1:Port.

oro_connect(Port, Conn) :-
    oro_connect(Port, Conn, []).

%!  oro_connect(+Port, -Conn, +Options) is det.
%
%   As oro_connect/2, with the options of tcp_connect/3:
%   nodelay(true) sends each flushed request at once (no Nagle delay
%   on requests written in several parts, such as large pipelined
%   batches).

oro_connect(Port, oro_conn(In, Out, Events, Replies), Options) :-
    must_be(between(1, 65535), Port),
    must_be(list, Options),
    tcp_connect('127.0.0.1':Port, Pair, Options),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(In, newline(posix)),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)),
    message_queue_create(Events),
    message_queue_create(Replies),
    debug(oro(test_client), 'connected to port ~w', [Port]).

%!  oro_disconnect(+Conn) is det.
%
%   Close the connection (errors of a peer that left first are
%   ignored) and free its queues.

oro_disconnect(oro_conn(In, Out, Events, Replies)) :-
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true),
    message_queue_destroy(Events),
    message_queue_destroy(Replies).

%!  oro_send(+Conn, +Method, +Params) is det.
%
%   Send a request: the method line, one line per parameter (text) and
%   `#end#`.

oro_send(oro_conn(_, Out, _, _), Method, Params) :-
    must_be(list, Params),
    atomics_to_string([Method, "\n"], First),
    findall(Line, ( member(Param, Params),
                    atomics_to_string([Param, "\n"], Line)
                  ),
            Lines),
    append([First|Lines], ["#end#\n"], Parts),
    atomics_to_string(Parts, Text),
    write(Out, Text),
    flush_output(Out).

%!  oro_send_raw(+Conn, +Data) is det.
%
%   Send Data as is and flush.  Data is text (written as UTF-8) or
%   bytes(Bytes), a list of bytes written without encoding (to send
%   invalid UTF-8).

oro_send_raw(oro_conn(_, Out, _, _), Data) :-
    (   Data = bytes(Bytes)
    ->  must_be(list(between(0, 255)), Bytes),
        setup_call_cleanup(
            set_stream(Out, encoding(octet)),
            ( forall(member(Byte, Bytes), put_byte(Out, Byte)),
              flush_output(Out)
            ),
            set_stream(Out, encoding(utf8)))
    ;   must_be(text, Data),
        write(Out, Data),
        flush_output(Out)
    ).

%!  oro_receive(+Conn, -Message) is det.
%!  oro_receive(+Conn, -Message, +TimeoutSeconds) is det.
%
%   Next message of any kind (replies put aside by oro_next_event/3
%   first).

oro_receive(Conn, Message) :-
    default_timeout(Timeout),
    oro_receive(Conn, Message, Timeout).

oro_receive(Conn, Message, Timeout) :-
    must_be_timeout(Timeout),
    Conn = oro_conn(_, _, _, Replies),
    (   thread_get_message(Replies, Message0, [timeout(0)])
    ->  Message = Message0
    ;   deadline(Timeout, Deadline),
        read_message(Conn, Deadline, Message)
    ).

%!  oro_call(+Conn, +Method, +Params, -Reply) is det.
%!  oro_call(+Conn, +Method, +Params, -Reply, +TimeoutSeconds) is det.
%
%   Send a request and wait for the next message that is not an event.
%   Events received meanwhile are queued for oro_next_event/3.

oro_call(Conn, Method, Params, Reply) :-
    default_timeout(Timeout),
    oro_call(Conn, Method, Params, Reply, Timeout).

oro_call(Conn, Method, Params, Reply, Timeout) :-
    must_be_timeout(Timeout),
    oro_send(Conn, Method, Params),
    deadline(Timeout, Deadline),
    reply(Conn, Deadline, Reply).

reply(Conn, Deadline, Reply) :-
    Conn = oro_conn(_, _, Events, Replies),
    (   thread_get_message(Replies, Reply0, [timeout(0)])
    ->  Reply = Reply0
    ;   read_message(Conn, Deadline, Message),
        (   Message = event(_, _)
        ->  thread_send_message(Events, Message),
            reply(Conn, Deadline, Reply)
        ;   Reply = Message
        )
    ).

%!  oro_next_event(+Conn, -Event) is det.
%!  oro_next_event(+Conn, -Event, +TimeoutSeconds) is det.
%
%   Next event(Id, Content), queued or read from the socket; other
%   messages read meanwhile are kept for oro_receive/3.  Event is
%   `timeout` or `end_of_file` if no event comes.

oro_next_event(Conn, Event) :-
    default_timeout(Timeout),
    oro_next_event(Conn, Event, Timeout).

oro_next_event(Conn, Event, Timeout) :-
    must_be_timeout(Timeout),
    Conn = oro_conn(_, _, Events, _),
    (   thread_get_message(Events, Event0, [timeout(0)])
    ->  Event = Event0
    ;   deadline(Timeout, Deadline),
        next_event(Conn, Deadline, Event)
    ).

next_event(Conn, Deadline, Event) :-
    Conn = oro_conn(_, _, _, Replies),
    read_message(Conn, Deadline, Message),
    (   Message = event(_, _)
    ->  Event = Message
    ;   final_message(Message)
    ->  Event = Message
    ;   thread_send_message(Replies, Message),
        next_event(Conn, Deadline, Event)
    ).

final_message(timeout).
final_message(end_of_file).


                 /*******************************
                 *     RAW DATA, HALF CLOSE     *
                 *******************************/

%!  oro_send_data(+Conn, +Parts) is det.
%
%   Write Parts in order, then flush once.  Each part is text(Text),
%   written as UTF-8, or octets(Bytes), Bytes a string or code list of
%   codes 0..255 written as raw bytes (invalid UTF-8, NUL bytes).  For
%   pipelined batches mixing well-formed and hostile requests; I/O
%   errors (a server that closed the connection) are not caught.

oro_send_data(oro_conn(_, Out, _, _), Parts) :-
    must_be(list, Parts),
    maplist(send_part(Out), Parts),
    flush_output(Out).

send_part(Out, text(Text)) :-
    !,
    must_be(text, Text),
    write(Out, Text).
send_part(Out, octets(Bytes)) :-
    !,
    (   string(Bytes)
    ->  String = Bytes
    ;   must_be(list(between(0, 255)), Bytes),
        string_codes(String, Bytes)
    ),
    setup_call_cleanup(
        set_stream(Out, encoding(octet)),
        write(Out, String),
        set_stream(Out, encoding(utf8))).
send_part(_, Part) :-
    domain_error(oro_data_part, Part).

%!  oro_half_close(+Conn) is det.
%
%   Close the output side of Conn (the server reads end of file) and
%   keep reading possible.  oro_disconnect/1 still releases Conn.

oro_half_close(oro_conn(_, Out, _, _)) :-
    catch(close(Out, [force(true)]), _, true).

%!  oro_drain(+Conn, -Messages, +TimeoutSeconds) is det.
%
%   Read every message until the server closes Conn, for at most
%   TimeoutSeconds in all.  Messages ends with `end_of_file`, or with
%   `timeout` if the connection stayed open.  At most 100,000 messages
%   are read (then the list ends with `timeout`).

oro_drain(Conn, Messages, Timeout) :-
    must_be_timeout(Timeout),
    deadline(Timeout, Deadline),
    drain_messages(Conn, Deadline, 100000, Messages).

drain_messages(Conn, Deadline, Budget, Messages) :-
    Conn = oro_conn(_, _, _, Replies),
    (   Budget =< 0
    ->  Messages = [timeout]
    ;   (   thread_get_message(Replies, Message0, [timeout(0)])
        ->  Message = Message0
        ;   read_message(Conn, Deadline, Message)
        ),
        (   final_message(Message)
        ->  Messages = [Message]
        ;   Messages = [Message|Rest],
            Budget1 is Budget - 1,
            drain_messages(Conn, Deadline, Budget1, Rest)
        )
    ).


                 /*******************************
                 *            READING           *
                 *******************************/

must_be_timeout(Timeout) :-
    must_be(number, Timeout),
    (   Timeout >= 0
    ->  true
    ;   domain_error(nonneg_timeout, Timeout)
    ).

deadline(Timeout, Deadline) :-
    get_time(Now),
    Deadline is Now + Timeout.

%   read_message(+Conn, +Deadline, -Message)

read_message(oro_conn(In, _, _, _), Deadline, Message) :-
    catch(read_message_(In, Deadline, Message), Error,
          read_error(Error, Message)),
    debug(oro(test_client), 'received ~q', [Message]),
    check_clients_read(Message).

%   check_clients_read(+Message)
%
%   Every value line the server sends must be read back by both real
%   clients (test/oro_client_parsers.pl): the value of a one-line `ok`
%   (the multi-line `help` text is for people) and the content of an
%   event.  A line either client would fail on makes the test fail.

check_clients_read(ok(Value)) :-
    !,
    (   sub_string(Value, _, _, _, "\n")
    ->  true
    ;   check_line(ok, Value)
    ).
check_clients_read(event(_, Content)) :-
    !,
    check_line(event, Content).
check_clients_read(_).

check_line(Kind, Line) :-
    (   reply_line_problem(Kind, Line, Problem)
    ->  throw(error(oro_client_read(Problem, Line), _))
    ;   true
    ).

read_error(error(timeout_error(_, _), _), timeout) :- !.
read_error(error(io_error(_, _), _), end_of_file) :- !.
read_error(error(socket_error(_, _), _), end_of_file) :- !.
read_error(error(existence_error(stream, _), _), end_of_file) :- !.
read_error(Error, _) :-
    throw(Error).

read_message_(In, Deadline, Message) :-
    read_line(In, Deadline, First),
    (   First == timeout
    ->  Message = timeout
    ;   First == end_of_file
    ->  Message = end_of_file
    ;   First == "ok"
    ->  body_lines(In, Deadline, Lines, Message, Done),
        (   Done == true
        ->  join_lines(Lines, Value),
            Message = ok(Value)
        ;   true
        )
    ;   First == "error"
    ->  body_lines(In, Deadline, Lines, Message, Done),
        (   Done == true
        ->  error_message(Lines, Message)
        ;   true
        )
    ;   First == "event"
    ->  body_lines(In, Deadline, Lines, Message, Done),
        (   Done == true
        ->  event_message(Lines, Message)
        ;   true
        )
    ;   First == "Closing now!"
    ->  Message = closing
    ;   Message = unexpected(First)
    ).

%   body_lines(+In, +Deadline, -Lines, -Message, -Done)
%
%   Lines up to `#end#`.  Done is `true`, or `false` with Message bound
%   to `timeout` or `end_of_file`.

body_lines(In, Deadline, Lines, Message, Done) :-
    read_line(In, Deadline, Line),
    (   Line == timeout
    ->  Message = timeout,
        Done = false
    ;   Line == end_of_file
    ->  Message = end_of_file,
        Done = false
    ;   Line == "#end#"
    ->  Lines = [],
        Done = true
    ;   Lines = [Line|Lines1],
        body_lines(In, Deadline, Lines1, Message, Done)
    ).

error_message([], error("", "")).
error_message([Name|Rest], error(Name, Message)) :-
    join_lines(Rest, Message).

event_message([], event("", "")).
event_message([Id|Rest], event(Id, Content)) :-
    join_lines(Rest, Content).

join_lines([], "").
join_lines([Line], Line) :-
    !.
join_lines([Line|Lines], Text) :-
    foldl(add_line, Lines, [Line], RevParts),
    reverse(RevParts, Parts),
    atomics_to_string(Parts, Text).

add_line(Line, Parts, [Line, "\n"|Parts]).

%   read_line(+In, +Deadline, -Line)
%
%   Line is a string, `timeout` or `end_of_file`.  wait_for_input/3
%   bounds the wait for the line to start (it sees data already in the
%   stream buffer); the stream timeout bounds a line that stops half
%   way.  read_line_to_codes/2 because read_line_to_string/2 stops at a
%   NUL character in SWI-Prolog 9.0.4.

read_line(In, Deadline, Line) :-
    get_time(Now),
    Remaining is Deadline - Now,
    (   Remaining =< 0
    ->  Line = timeout
    ;   wait_for_input([In], Ready, Remaining),
        (   Ready == []
        ->  Line = timeout
        ;   set_stream(In, timeout(Remaining)),
            read_line_to_codes(In, Codes),
            (   Codes == end_of_file
            ->  Line = end_of_file
            ;   string_codes(Line, Codes)
            )
        )
    ).
