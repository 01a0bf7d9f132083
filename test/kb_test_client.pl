:- module(kb_test_client,
          [ kb_connect/2,               % +Port, -Conn
            kb_disconnect/1,            % +Conn
            kb_call/4,                  % +Conn, +Method, +Args, -Reply
            kb_call/5,                  % +Conn, +Method, +Args, +KWArgs, -Reply
            kb_send_raw/2,              % +Conn, +Text
            kb_receive/3,               % +Conn, -Message, +Timeout
            kb_next_event/3,            % +Conn, -Event, +Timeout
            kb_no_event/2               % +Conn, +Timeout
          ]).
:- use_module(library(socket)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(readutil)).
:- use_module(library(http/json)).

/** <module> A KB-API client for the tests

Speaks the KB-API dialect as pykb does: the method, one JSON line per
argument, `{"kwargs": {...}}` for keyword arguments, `#end#`.  Replies:

  - ok(Value)           the JSON value (a dict, list, string, number,
                        `true`, `false` or `null`)
  - ok                  `ok` and `#end#` alone
  - error(Name, Message)
  - end_of_file         the server closed the connection
  - timeout

Events that arrive while waiting for a reply are kept, in order, for
kb_next_event/3 as event(Id, Value).
*/

%!  kb_connect(+Port, -Conn) is det.

kb_connect(Port, kb_conn(In, Out, Events)) :-
    must_be(between(1, 65535), Port),
    tcp_connect('127.0.0.1':Port, Pair, []),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(Out, encoding(utf8)),
    message_queue_create(Events).

%!  kb_disconnect(+Conn) is det.

kb_disconnect(kb_conn(In, Out, Events)) :-
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true),
    message_queue_destroy(Events).

%!  kb_call(+Conn, +Method, +Args, -Reply) is det.
%!  kb_call(+Conn, +Method, +Args, +KWArgs, -Reply) is det.
%
%   Send Method with the JSON terms Args (and the dict KWArgs) and wait
%   (10 s at most) for the reply.

kb_call(Conn, Method, Args, Reply) :-
    kb_call(Conn, Method, Args, _{}, Reply).

kb_call(Conn, Method, Args, KWArgs, Reply) :-
    Conn = kb_conn(_, Out, _),
    findall(Line, ( member(Arg, Args), json_line(Arg, Line) ), Lines0),
    (   dict_pairs(KWArgs, _, [])
    ->  Lines = Lines0
    ;   json_line(_{kwargs:KWArgs}, KW),
        append(Lines0, [KW], Lines)
    ),
    atomic_list_concat([Method|Lines], '\n', Head),
    format(Out, "~w\n#end#\n", [Head]),
    flush_output(Out),
    reply(Conn, Reply).

json_line(Term, Line) :-
    with_output_to(string(Line),
                   json_write_dict(current_output, Term, [width(0)])).

reply(Conn, Reply) :-
    kb_receive(Conn, Message, 10),
    (   Message = event(_, _)
    ->  Conn = kb_conn(_, _, Events),
        thread_send_message(Events, Message),
        reply(Conn, Reply)
    ;   Reply = Message
    ).

%!  kb_send_raw(+Conn, +Text) is det.

kb_send_raw(kb_conn(_, Out, _), Text) :-
    write(Out, Text),
    flush_output(Out).

%!  kb_receive(+Conn, -Message, +Timeout) is det.
%
%   The next message, whatever it is.

kb_receive(kb_conn(In, _, _), Message, Timeout) :-
    set_stream(In, timeout(Timeout)),
    catch(read_lines(In, Lines), error(timeout_error(_, _), _),
          Lines = timeout),
    message(Lines, Message).

read_lines(In, Lines) :-
    read_line_to_string(In, Line),
    (   Line == end_of_file
    ->  Lines = end_of_file
    ;   Line == "#end#"
    ->  Lines = []
    ;   Lines = [Line|Rest],
        read_lines(In, Rest)
    ).

message(timeout, timeout) :- !.
message(end_of_file, end_of_file) :- !.
message(Lines, end_of_file) :-
    \+ is_list(Lines),
    !.
message(["ok"], ok) :- !.
message(["ok", JSON], ok(Value)) :-
    !,
    atom_json_dict(JSON, Value, [value_string_as(string)]).
message(["error", Name, Text], error(Name, Text)) :- !.
message(["event", Id, JSON], event(Id, Value)) :-
    !,
    atom_json_dict(JSON, Value, [value_string_as(string)]).
message(Lines, unexpected(Lines)).

%!  kb_next_event(+Conn, -Event, +Timeout) is det.
%
%   The next event(Id, Value), or `timeout` if none comes within
%   Timeout seconds.

kb_next_event(Conn, Event, Timeout) :-
    Conn = kb_conn(_, _, Events),
    (   thread_get_message(Events, Event0, [timeout(0)])
    ->  Event = Event0
    ;   kb_receive(Conn, Message, Timeout),
        (   Message = event(_, _)
        ->  Event = Message
        ;   Event = Message
        )
    ).

%!  kb_no_event(+Conn, +Timeout) is semidet.
%
%   No event is waiting, nor comes within Timeout seconds.

kb_no_event(Conn, Timeout) :-
    kb_next_event(Conn, timeout, Timeout).
