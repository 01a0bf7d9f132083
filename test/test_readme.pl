/*  The examples of README.md, run as written.

    An example is run when a marker comment stands right before its
    code block (blank lines apart):

        <!-- readme-test: telnet [SERVER OPTION ...] -->
        <!-- readme-test: prolog -->

    Unmarked blocks are left alone, so sections can be added without
    touching this file; a marked block that no longer runs as written
    fails its test, named after the line of its marker.

    - telnet: the real server (swipl server/oro_server.pl, in the
      checkout) with the options of the marker; the block's requests
      (up to each `#end#`) are sent on one connection and each reply
      (up to its `#end#`; the line after a `close`) must be the
      block's lines.  Lines starting with `$ ` are commands, skipped.
    - prolog: a toplevel session: `swipl -p library=prolog` in the
      checkout, each `?- Goal.` run in turn by
      test/fixtures/readme_toplevel.pl; the lines under a goal must be
      how its output and answers begin (a line ` ;`-terminated asks
      for one more answer; `...` stops the comparison).  A goal shown
      without lines must succeed.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(socket)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).

%   readme_example(-Line, -Kind, -Args, -Block): a marked example of
%   README.md; Line is the line of its marker, Block its lines without
%   the 4-space indent.

readme_example(Line, Kind, Args, Block) :-
    test_checkout_path('README.md', File),
    read_file_to_string(File, Text, []),
    split_string(Text, "\n", "", Lines),
    nth1(Line, Lines, Marker),
    readme_marker(Marker, Kind, Args),
    Next is Line + 1,
    findall(L, ( nth1(I, Lines, L), I >= Next ), After),
    readme_block(After, Block).

readme_marker(Text, Kind, Args) :-
    split_string(Text, "", " ", [Trimmed]),
    string_concat("<!-- readme-test:", Rest0, Trimmed),
    string_concat(Rest, "-->", Rest0),
    split_string(Rest, " ", " ", Words0),
    exclude(==(""), Words0, [KindText|ArgTexts]),
    atom_string(Kind, KindText),
    maplist(atom_string, Args, ArgTexts).

%   readme_block(+Lines, -Block): the indented block at the start of
%   Lines (after blank lines); blank lines inside it are kept.

readme_block(Lines, Block) :-
    readme_skip_blank(Lines, Rest),
    readme_indented(Rest, Block0),
    readme_trim_blank(Block0, Block).

readme_skip_blank([L|Ls], Rest) :-
    L == "",
    !,
    readme_skip_blank(Ls, Rest).
readme_skip_blank(Ls, Ls).

readme_indented([L|Ls], [Body|Bs]) :-
    (   string_concat("    ", Body, L)
    ->  true
    ;   L == "",
        readme_skip_blank(Ls, [Next|_]),
        sub_string(Next, 0, 4, _, "    ")
    ->  Body = ""
    ),
    !,
    readme_indented(Ls, Bs).
readme_indented(_, []).

readme_trim_blank(Block0, Block) :-
    reverse(Block0, R0),
    readme_skip_blank(R0, R),
    reverse(R, Block).

                 /*******************************
                 *            TELNET            *
                 *******************************/

%   readme_exchanges(+Lines, -Exchanges): Request-Reply pairs of lines.

readme_exchanges([], []).
readme_exchanges([L|Ls], Xs) :-
    sub_string(L, 0, _, _, "$ "),
    !,
    readme_exchanges(Ls, Xs).
readme_exchanges(Lines, [Request-Reply|Xs]) :-
    append(Request, ["#end#"|Rest0], Lines),
    !,
    (   Request = [Method|_],
        string_lower(Method, "close")
    ->  Rest0 = [Line|Rest],
        Reply = [Line]
    ;   append(Reply0, ["#end#"|Rest], Rest0)
    ->  append(Reply0, ["#end#"], Reply)
    ),
    readme_exchanges(Rest, Xs).

readme_telnet(Args, Exchanges, Replies) :-
    test_cli_server(Args, Port, readme_session(Port, Exchanges, Replies), _).

readme_session(Port, Exchanges, Replies) :-
    setup_call_cleanup(
        tcp_connect('127.0.0.1':Port, Pair, []),
        ( stream_pair(Pair, In, Out),
          set_stream(In, encoding(utf8)),
          set_stream(Out, encoding(utf8)),
          maplist(readme_exchange(In, Out), Exchanges, Replies)
        ),
        close(Pair, [force(true)])).

readme_exchange(In, Out, Request-Expected, Reply) :-
    forall(member(Line, Request), format(Out, "~s~n", [Line])),
    format(Out, "#end#~n", []),
    flush_output(Out),
    length(Expected, N),
    length(Reply, N),
    maplist(read_line_to_string(In), Reply).

                 /*******************************
                 *            PROLOG            *
                 *******************************/

%   readme_goals(+Lines, -Goals): goal(Text, Solutions, Expected) for
%   each `?- ` line of Lines.

readme_goals([], []).
readme_goals([L|Ls], Goals) :-
    (   string_concat("?- ", Goal0, L)
    ->  split_string(Goal0, "", " ", [Goal1]),
        string_concat(Goal, ".", Goal1),
        readme_expected(Ls, Expected, Rest),
        include(readme_more, Expected, More),
        length(More, NMore),
        N is NMore + 1,
        Goals = [goal(Goal, N, Expected)|Goals1],
        readme_goals(Rest, Goals1)
    ;   readme_goals(Ls, Goals)
    ).

readme_expected([L|Ls], [L|Es], Rest) :-
    \+ sub_string(L, 0, _, _, "?- "),
    \+ sub_string(L, 0, _, _, "$ "),
    !,
    readme_expected(Ls, Es, Rest).
readme_expected(Rest, [], Rest).

readme_more(Line) :-
    sub_string(Line, _, _, 0, " ;").

readme_toplevel(Goals, Transcripts) :-
    test_checkout_path('.', Checkout),
    test_fixture('readme_toplevel.pl', Runner),
    tmp_file(readme_session, Session),
    setup_call_cleanup(
        open(Session, write, S),
        forall(member(goal(G, N, _), Goals),
               format(S, "~q.~n", [goal(G, N)])),
        close(S)),
    setup_call_cleanup(
        process_create(path(timeout),
                       ['60', swipl, '-p', 'library=prolog', Runner, Session],
                       [ cwd(Checkout), stdout(pipe(Out)), stderr(null),
                         process(Pid)
                       ]),
        ( read_string(Out, _, Text),
          process_wait(Pid, _)
        ),
        close(Out)),
    delete_file(Session),
    split_string(Text, "\n", "", Lines),
    readme_transcripts(Lines, Transcripts).

readme_transcripts(Lines, [T|Ts]) :-
    append(T, ["<end>"|Rest], Lines),
    !,
    readme_transcripts(Rest, Ts).
readme_transcripts(_, []).

%   readme_mismatch(+Goal, +Transcript, -Mismatch): the first line where
%   the README and the run differ, or `none`.

readme_mismatch(goal(Goal, _, Expected0), Transcript, Mismatch) :-
    (   append(Expected, ["..."], Expected0)
    ->  true
    ;   Expected = Expected0
    ),
    (   Expected == []
    ->  (   Transcript = [First|_],
            ( First == "false." ; sub_string(First, 0, _, _, "ERROR") )
        ->  Mismatch = Goal-First
        ;   Mismatch = none
        )
    ;   readme_prefix(Expected, Transcript, Mismatch0),
        (   Mismatch0 == none
        ->  Mismatch = none
        ;   Mismatch = Goal-Mismatch0
        )
    ).

readme_prefix([], _, none) :-
    !.
readme_prefix([E|Es], [T|Ts], Mismatch) :-
    E == T,
    !,
    readme_prefix(Es, Ts, Mismatch).
readme_prefix([E|_], Ts, expected(E)-got(T)) :-
    (   Ts = [T|_]
    ->  true
    ;   T = end
    ).

                 /*******************************
                 *            TESTS             *
                 *******************************/

:- begin_tests(readme).

test(examples_are_marked, true(Kinds == [prolog, telnet])) :-
    findall(K, readme_example(_, K, _, _), Ks),
    sort(Ks, Kinds).

test(example, [ forall(readme_example(Line, telnet, Args, Block)),
                true(Line-Replies == Line-Expected)
              ]) :-
    once(readme_exchanges(Block, Exchanges)),
    pairs_values(Exchanges, Expected),
    once(readme_telnet(Args, Exchanges, Replies)).

test(example, [ forall(readme_example(Line, prolog, _, Block)),
                true(Line-Mismatches == Line-[])
              ]) :-
    readme_goals(Block, Goals),
    readme_toplevel(Goals, Transcripts),
    length(Goals, N),
    length(Transcripts, NT),
    assertion(NT == N),
    maplist(readme_mismatch, Goals, Transcripts, Mismatches0),
    exclude(==(none), Mismatches0, Mismatches).

:- end_tests(readme).
