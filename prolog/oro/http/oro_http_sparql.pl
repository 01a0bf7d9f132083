:- module(oro_http_sparql,
          [ oro_http_sparql/1           % +Request
          ]).
:- use_module(library(http/http_dispatch)).
:- use_module(library(http/http_parameters)).
:- use_module(library(http/http_header)).
:- use_module(library(http/http_client)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module(library(oro/sparql/oro_sparql), [oro_sparql/4, oro_sparql_result_text/3]).
:- use_module(library(oro/oro_store), [oro_store_read/1]).

/** <module> The SPARQL 1.1 Protocol endpoint

`/sparql` answers SPARQL queries over the robot's model,
`/sparql/AGENT` over the model of AGENT, as the SPARQL 1.1 Protocol
says: a query by GET (`?query=...`), by POST of a form
(`application/x-www-form-urlencoded`, field `query`) or by POST of the
query itself (`application/sparql-query`).  Parameters:

  - `default-graph-uri` and `named-graph-uri` (repeatable): the
    dataset, overriding the query's FROM and FROM NAMED (see
    oro_sparql_graph/2 and the page `/graphs`);
  - `infer`: `true` (default) queries the inference closure of the
    model, `false` the triples asserted in it (GraphDB's convention);
  - `format`: `json`, `xml`, `csv`, `tsv`, `turtle` or `ntriples`,
    overriding the `Accept` header (for browsers).

Results are negotiated with `Accept`: SPARQL JSON
(`application/sparql-results+json`, also `application/json`), XML
(`application/sparql-results+xml`, `application/xml`, `text/xml`), CSV
(`text/csv`) or TSV (`text/tab-separated-values`) for SELECT and ASK;
Turtle (`text/turtle`) or N-Triples (`application/n-triples`,
`text/plain`) for CONSTRUCT and DESCRIBE.  No `Accept` header or one
accepting any type gives JSON or Turtle.  Errors: 400 for a malformed request or query
(with the message as text/plain), 404 for an unknown agent, 406 when no
acceptable format is offered, 403 for an update (the endpoint is
read-only: nothing changes), 503 past the query time limit
(`oro_query:time_limit`).
*/

:- http_handler(root(sparql), oro_http_sparql, [prefix, methods([get, post])]).

%!  oro_http_sparql(+Request) is det.
%
%   The HTTP handler of `/sparql` and `/sparql/AGENT`.

oro_http_sparql(Request) :-
    catch(answer(Request), Reply, reply_error(Reply)).

answer(Request) :-
    model(Request, Model),
    request_query(Request, Text, Params),
    option_values('default-graph-uri', Params, Defaults),
    option_values('named-graph-uri', Params, Named),
    infer(Params, Infer),
    findall(default_graph(G), member(G, Defaults), DefaultOptions),
    findall(named_graph(G), member(G, Named), NamedOptions),
    append(DefaultOptions, NamedOptions, GraphOptions),
    debug(oro(http), 'SPARQL ~w (infer ~w, ~q): ~w',
          [Model, Infer, Defaults, Text]),
    oro_store_read(oro_sparql(Model, Text, Result,
                              [infer(Infer)|GraphOptions])),
    negotiate(Request, Params, Result, Format, Type),
    oro_sparql_result_text(Format, Result, Body),
    format('Content-Type: ~w; charset=UTF-8~n~n', [Type]),
    write(Body).

%   model(+Request, -Model): `/sparql` is the robot's model, `/sparql/A`
%   the model of agent A.

model(Request, Model) :-
    (   memberchk(path_info(Info), Request),
        atom_concat('/', Agent, Info),
        Agent \== ''
    ->  uri_encoded(path, Model, Agent)
    ;   Model = myself
    ).

%   request_query(+Request, -Text, -Params): the query text and the
%   other parameters (Name=Value), from the URL or the form body.

request_query(Request, Text, Params) :-
    memberchk(method(Method), Request),
    (   Method == post,
        memberchk(content_type(Type0), Request),
        media_type(Type0, Type),
        Type \== 'application/x-www-form-urlencoded'
    ->  (   Type == 'application/sparql-query'
        ->  http_read_data(Request, Text0, [to(string)]),
            url_params(Request, Params),
            (   memberchk(query=_, Params)
            ->  throw(reply(400, "a query both in the body and in the URL"))
            ;   true
            ),
            Text = Text0
        ;   Type == 'application/sparql-update'
        ->  throw(reply(403, "updates are refused: this endpoint is read-only"))
        ;   format(string(Msg), "unsupported content type ~w", [Type]),
            throw(reply(415, Msg))
        )
    ;   http_parameters(Request, [], [form_data(Params)]),
        (   memberchk(update=_, Params)
        ->  throw(reply(403, "updates are refused: this endpoint is read-only"))
        ;   findall(Q, member(query=Q, Params), Qs),
            (   Qs = [Text]
            ->  true
            ;   Qs == []
            ->  throw(reply(400, "no query parameter"))
            ;   throw(reply(400, "more than one query parameter"))
            )
        )
    ).

url_params(Request, Params) :-
    (   memberchk(search(Params0), Request)
    ->  Params = Params0
    ;   Params = []
    ).

media_type(Type0, Type) :-
    (   sub_atom(Type0, B, _, _, ';')
    ->  sub_atom(Type0, 0, B, _, Type1)
    ;   Type1 = Type0
    ),
    normalize_space(atom(Type2), Type1),
    downcase_atom(Type2, Type).

option_values(Name, Params, Values) :-
    findall(V, member(Name=V, Params), Values).

infer(Params, Infer) :-
    (   memberchk(infer=Value, Params)
    ->  (   memberchk(Value-Infer, [true-true, false-false])
        ->  true
        ;   throw(reply(400, "infer must be true or false"))
        )
    ;   Infer = true
    ).

		 /*******************************
		 *     CONTENT NEGOTIATION      *
		 *******************************/

%   result_type(?Kind, ?Format, ?Type): the media types of the results
%   of a Kind of query, preferred first.

result_type(bindings, json, 'application/sparql-results+json').
result_type(bindings, xml,  'application/sparql-results+xml').
result_type(bindings, csv,  'text/csv').
result_type(bindings, tsv,  'text/tab-separated-values').
result_type(bindings, json, 'application/json').
result_type(bindings, xml,  'application/xml').
result_type(bindings, xml,  'text/xml').

result_type(graph, turtle,   'text/turtle').
result_type(graph, ntriples, 'application/n-triples').
result_type(graph, ntriples, 'text/plain').
result_type(graph, turtle,   'application/x-turtle').

result_kind(select(_, _), bindings).
result_kind(ask(_), bindings).
result_kind(graph(_), graph).

negotiate(Request, Params, Result, Format, Type) :-
    result_kind(Result, Kind),
    (   memberchk(format=F, Params)
    ->  (   result_type(Kind, F, Type)
        ->  Format = F
        ;   format(string(Msg), "format ~w is not offered for this query", [F]),
            throw(reply(406, Msg))
        )
    ;   accepted(Request, Ranges),
        (   member(media(Main/Sub, _, Q, _), Ranges),
            Q > 0,
            result_type(Kind, Format, Type),
            atomic_list_concat([Main, Sub], '/', Type)
        ->  true
        ;   findall(T, result_type(Kind, _, T), Ts),
            atomic_list_concat(Ts, ', ', Offered),
            format(string(Msg), "no acceptable result format; offered: ~w",
                   [Offered]),
            throw(reply(406, Msg))
        )
    ).

%   accepted(+Request, -Ranges): the media ranges of Accept, best
%   first (a missing or malformed header accepts anything).

accepted(Request, Ranges) :-
    (   memberchk(accept(Header), Request),
        catch(http_parse_header_value(accept, Header, Ranges0), _, fail)
    ->  predsort(by_quality, Ranges0, Ranges)
    ;   Ranges = [media(_/_, [], 1.0, [])]
    ).

by_quality(Order, media(T1, P1, Q1, _), media(T2, P2, Q2, _)) :-
    compare(O0, Q2, Q1),
    (   O0 == (=)
    ->  specificity(T1, S1),
        specificity(T2, S2),
        compare(O1, S2, S1),
        (   O1 == (=)
        ->  compare(Order, T1-P1, T2-P2)
        ;   Order = O1
        )
    ;   Order = O0
    ).

specificity(M/S, N) :-
    (   var(M)
    ->  N = 0
    ;   var(S)
    ->  N = 1
    ;   N = 2
    ).

		 /*******************************
		 *            ERRORS            *
		 *******************************/

reply_error(reply(Status, Message)) :-
    !,
    reply_text(Status, Message).
reply_error(error(syntax_error(oro_sparql(Message, _)), _)) :-
    !,
    format(string(Text), "SPARQL syntax error: ~w", [Message]),
    reply_text(400, Text).
reply_error(error(existence_error(agent, Model), _)) :-
    !,
    format(string(Text), "no such agent model: ~w", [Model]),
    reply_text(404, Text).
reply_error(error(resource_error(oro_query_time_limit(Seconds)), _)) :-
    !,
    format(string(Text), "the query ran longer than the time limit (~w s)",
           [Seconds]),
    reply_text(503, Text).
reply_error(error(Formal, _)) :-
    !,
    format(string(Text), "error: ~q", [Formal]),
    reply_text(500, Text).
reply_error(Other) :-
    throw(Other).

reply_text(Status, Message) :-
    debug(oro(http), 'SPARQL reply ~w: ~w', [Status, Message]),
    format('Status: ~d~nContent-Type: text/plain; charset=UTF-8~n~n~w~n',
           [Status, Message]).
